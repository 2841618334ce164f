"""Snapshot tests of robot images for pytest.

    from urdfsnap.testing import assert_matches_snapshot

    def test_arm_home():
        image = urdfsnap.Robot("arm.urdf.xacro").render(size=(320, 240))
        assert_matches_snapshot(image, "tests/snapshots/arm_home.png")

The golden PNG is written when it is missing or when the environment has URDFSNAP_UPDATE=1;
otherwise the image is compared with urdfsnap.diff's defaults (the tolerance of `urdfsnap diff`).
"""

import os

import urdfsnap


def _beside(path, what):
    stem, extension = os.path.splitext(os.fspath(path))
    return f"{stem}.{what}{extension or '.png'}"


def assert_matches_snapshot(image, path, **tolerance):
    """Asserts that `image` (H×W×3 uint8) matches the golden PNG at `path`. Writes the golden when it
    is missing or URDFSNAP_UPDATE=1. On a mismatch writes PATH.expected.png, PATH.actual.png and
    PATH.diff.png beside the golden and fails (AssertionError) naming them; on a match removes
    those left by an earlier failure. `tolerance`: diff's max_delta, max_fraction, max_mean."""
    path = os.fspath(path)
    outputs = {what: _beside(path, what) for what in ("expected", "actual", "diff")}
    if os.environ.get("URDFSNAP_UPDATE") == "1" or not os.path.exists(path):
        folder = os.path.dirname(path)
        if folder:
            os.makedirs(folder, exist_ok=True)
        urdfsnap.write_png(image, path)
        return
    expected = urdfsnap.read_png(path)
    if expected.shape != image.shape:
        result = None
    else:
        result = urdfsnap.diff(expected, image, **tolerance)
        if result.passed:
            for output in outputs.values():
                if os.path.exists(output):
                    os.remove(output)
            return
    urdfsnap.write_png(expected, outputs["expected"])
    urdfsnap.write_png(image, outputs["actual"])
    if result is None:
        problem = f"size {image.shape[1]}x{image.shape[0]}, the snapshot's {expected.shape[1]}x{expected.shape[0]}"
    else:
        urdfsnap.write_png(result.image, outputs["diff"])
        problem = result.description
    raise AssertionError(
        f"{path}: the image differs from the snapshot ({problem}); see {outputs['expected']}, "
        f"{outputs['actual']}" + ("" if result is None else f", {outputs['diff']}")
        + " (URDFSNAP_UPDATE=1 accepts the new image)")
