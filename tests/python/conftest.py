# Shared fixtures of the Python package's tests: the repository's robots, the urdfsnap binary to
# compare with (URDFSNAP_BINARY, set by CTest; else build/urdfsnap), and a small URDF of known
# geometry for the depth and label tests.
import os
import pathlib
import subprocess

import pytest

import urdfsnap

ROOT = pathlib.Path(__file__).resolve().parents[2]
MRM = ROOT / "models" / "mrm_description" / "urdf" / "mrm.urdf"
BIGBOT = ROOT / "tests" / "data" / "bigbot" / "bigbot.urdf.xacro"

# Two unit cubes 2 m apart along y: link "left" at y = +1, link "right" at y = -1, joined by a
# prismatic joint along z (limits -1..1) and a mimic joint.
BOXES = """<?xml version="1.0"?>
<robot name="boxes">
  <link name="base"/>
  <link name="left"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
  <link name="right"><visual><geometry><box size="1 1 1"/></geometry></visual></link>
  <link name="follower"/>
  <joint name="lift" type="prismatic">
    <parent link="base"/><child link="left"/><origin xyz="0 1 0"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="fixed" type="fixed">
    <parent link="base"/><child link="right"/><origin xyz="0 -1 0"/>
  </joint>
  <joint name="copy" type="prismatic">
    <parent link="base"/><child link="follower"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/>
    <mimic joint="lift" multiplier="2" offset="0.5"/>
  </joint>
</robot>
"""


@pytest.fixture(scope="session")
def binary():
    return os.environ.get("URDFSNAP_BINARY", str(ROOT / "build" / "urdfsnap"))


@pytest.fixture(scope="session")
def mrm():
    return urdfsnap.Robot(MRM)


@pytest.fixture
def boxes_path(tmp_path):
    path = tmp_path / "boxes.urdf"
    path.write_text(BOXES)
    return path


def run_cli(binary, *args):
    """Runs the urdfsnap binary; returns its completed process (text output)."""
    return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, check=False)
