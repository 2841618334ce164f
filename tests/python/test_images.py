# Images from Python: PNG reading and writing, urdfsnap.diff with `urdfsnap diff`'s tolerance,
# urdfsnap.testing.assert_matches_snapshot, and show() outside a notebook.
import numpy as np
import pytest

import urdfsnap
from urdfsnap.testing import assert_matches_snapshot


@pytest.fixture
def picture():
    rng = np.random.default_rng(7)
    return rng.integers(0, 256, size=(40, 60, 3), dtype=np.uint8)


def test_png_round_trip(tmp_path, picture):
    urdfsnap.write_png(picture, tmp_path / "p.png")
    np.testing.assert_array_equal(urdfsnap.read_png(tmp_path / "p.png"), picture)
    assert urdfsnap.encode_png(picture) == (tmp_path / "p.png").read_bytes()
    with pytest.raises(urdfsnap.Error, match="missing.png"):
        urdfsnap.read_png(tmp_path / "missing.png")
    with pytest.raises(urdfsnap.Error, match="H×W×3"):
        urdfsnap.write_png(np.zeros((4, 4)), tmp_path / "flat.png")


def test_diff_passes_noise_and_fails_changes(picture, tmp_path):
    same = urdfsnap.diff(picture, picture.copy())
    assert same.passed and same.fraction == 0 and same.max_delta == 0 and bool(same)
    changed = picture.copy()
    changed[10:20, 10:20] ^= 0x80
    result = urdfsnap.diff(picture, changed)
    assert not result.passed and result.max_delta == 128
    assert result.fraction == pytest.approx(100 / (40 * 60))
    assert result.image.shape == picture.shape
    assert tuple(result.image[15, 15]) == (255, 0, 255)
    assert urdfsnap.diff(picture, changed, max_delta=200, max_mean=10).passed
    urdfsnap.write_png(picture, tmp_path / "p.png")
    assert urdfsnap.diff(tmp_path / "p.png", str(tmp_path / "p.png")).passed
    with pytest.raises(urdfsnap.Error, match="60x40"):
        urdfsnap.diff(picture, picture[:20])


def test_snapshot_written_then_matched_then_failed(tmp_path, picture, monkeypatch):
    golden = tmp_path / "snapshots" / "robot.png"
    assert_matches_snapshot(picture, golden)  # missing: written
    np.testing.assert_array_equal(urdfsnap.read_png(golden), picture)
    assert_matches_snapshot(picture, golden)
    changed = picture.copy()
    changed[:10] = 0
    with pytest.raises(AssertionError) as failed:
        assert_matches_snapshot(changed, golden)
    for what in ("expected", "actual", "diff"):
        path = tmp_path / "snapshots" / f"robot.{what}.png"
        assert path.exists() and str(path) in str(failed.value)
    np.testing.assert_array_equal(urdfsnap.read_png(tmp_path / "snapshots" / "robot.actual.png"), changed)
    monkeypatch.setenv("URDFSNAP_UPDATE", "1")
    assert_matches_snapshot(changed, golden)
    monkeypatch.delenv("URDFSNAP_UPDATE")
    assert_matches_snapshot(changed, golden)
    assert not (tmp_path / "snapshots" / "robot.diff.png").exists()


def test_show_outside_a_notebook_returns_something_a_notebook_shows(picture):
    assert urdfsnap.show(picture)._repr_png_() == urdfsnap.encode_png(picture)
