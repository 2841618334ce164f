# The examples in examples/python run and make what they say: the contact sheet of random poses
# (few and small here), the notebook-style script, and the snapshot test of mrm against its
# committed goldens.
import os
import subprocess
import sys

import numpy as np

import urdfsnap
from conftest import MRM, ROOT

EXAMPLES = ROOT / "examples" / "python"


def run_example(*args, cwd):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run([sys.executable, *map(str, args)], cwd=cwd, env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_contact_sheet_of_random_poses(tmp_path):
    sheet = tmp_path / "sheet.png"
    run_example(EXAMPLES / "contact_sheet.py", MRM, "-o", sheet, "--count", "6", "--size", "40x30", cwd=tmp_path)
    image = urdfsnap.read_png(sheet)
    assert image.shape == (2 * 30, 3 * 40, 3)
    tiles = [image[r * 30:(r + 1) * 30, c * 40:(c + 1) * 40] for r in range(2) for c in range(3)]
    assert all(np.any(tile[:, :, 0].astype(int) > tile[:, :, 1].astype(int) + 60) for tile in tiles)  # red mrm
    assert len({tile.tobytes() for tile in tiles}) == 6  # six different poses


def test_notebook_script_runs_as_a_script(tmp_path):
    (tmp_path / "models").symlink_to(ROOT / "models")
    printed = run_example(EXAMPLES / "notebook.py", cwd=tmp_path)
    assert "links seen" in printed
    assert urdfsnap.read_png(tmp_path / "output" / "notebook_sweep.png").shape == (120, 6 * 160, 3)


def test_snapshot_example_matches_its_goldens(tmp_path):
    run_example("-m", "pytest", "-q", "-p", "no:cacheprovider", EXAMPLES / "test_mrm_snapshots.py", cwd=tmp_path)
