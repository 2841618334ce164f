# A pytest snapshot test of a robot package: each pose of the mrm arm (models/mrm_description)
# rendered and compared with its golden PNG in snapshots/ beside this file. The first run writes
# the goldens (commit them); URDFSNAP_UPDATE=1 rewrites them after an intended change. A failure
# leaves NAME.expected.png, NAME.actual.png and NAME.diff.png beside the golden.
#
#   python3 -m pytest examples/python/test_mrm_snapshots.py
import pathlib

import pytest

import urdfsnap
from urdfsnap.testing import assert_matches_snapshot

HERE = pathlib.Path(__file__).resolve().parent
PACKAGE = HERE.parents[1] / "models" / "mrm_description"

POSES = {
    "zero": {},
    "reach": {"link_01__link_02": -0.9, "link_02__link_03": 1.3},
    "twist": {"base_link__link_01": 1.2, "link_03__link_04": -1.0},
}


@pytest.fixture(scope="module")
def robot():
    return urdfsnap.Robot(PACKAGE / "urdf" / "mrm.xacro", packages={"mrm_description": PACKAGE})


@pytest.mark.parametrize("name", POSES)
def test_pose_matches_snapshot(robot, name):
    image = robot.render(POSES[name], fit=True, size=(320, 240))
    assert_matches_snapshot(image, HERE / "snapshots" / f"mrm_{name}.png")
