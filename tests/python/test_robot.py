# urdfsnap.Robot without drawing: loading URDF and xacro, links, joints, defaults, and the errors
# the command line names (urdfsnap.Error with its message).
import pytest

import urdfsnap
from conftest import BIGBOT, MRM, ROOT, run_cli


def test_links_and_joints_as_the_urdf_gives_them(boxes_path):
    robot = urdfsnap.Robot(boxes_path)
    assert robot.name == "boxes"
    assert robot.links == ["base", "left", "right", "follower"]
    assert [j.name for j in robot.joints] == ["lift", "fixed", "copy"]
    assert [j.type for j in robot.joints] == ["prismatic", "fixed", "prismatic"]
    lift, fixed, copy = robot.joints
    assert (lift.lower, lift.upper, lift.default, lift.mimic) == (-1, 1, 0, None)
    assert (fixed.lower, fixed.upper) == (None, None)
    assert (copy.mimic.joint, copy.mimic.multiplier, copy.mimic.offset) == ("lift", 2, 0.5)
    assert copy.default == 0.5  # follows lift's default 0
    assert robot.joint_names == ["lift"]
    assert robot.default_positions() == {"lift": 0.0}


def test_a_default_outside_the_limits_is_their_middle(tmp_path):
    path = tmp_path / "raised.urdf"
    path.write_text("""<robot name="r"><link name="a"/><link name="b"/>
      <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
        <limit lower="0.5" upper="1.5" effort="1" velocity="1"/></joint></robot>""")
    assert urdfsnap.Robot(str(path)).default_positions() == {"j": 1.0}


def test_xacro_with_arguments_and_packages():
    robot = urdfsnap.Robot(ROOT / "models/mrm_description/urdf/mrm.xacro",
                           packages={"mrm_description": ROOT / "models/mrm_description"})
    assert robot.links == urdfsnap.Robot(MRM).links
    bigbot = urdfsnap.Robot(BIGBOT)
    assert sum(j.mimic is not None for j in bigbot.joints) == 4
    assert len(bigbot.joint_names) == 42


def test_xacro_text_is_the_commands(binary):
    path = ROOT / "models/mrm_description/urdf/mrm.xacro"
    packages = {"mrm_description": str(ROOT / "models/mrm_description")}
    expected = run_cli(binary, "xacro", path, "--package", f"mrm_description={packages['mrm_description']}")
    assert expected.returncode == 0, expected.stderr
    assert urdfsnap.xacro(path, packages=packages) == expected.stdout


@pytest.mark.parametrize("content, message", [
    (None, "cannot read the model file"),
    ("<robot name='r'><link name='a'/><joint name='j' type='revolute'><parent link='a'/>"
     "<child link='zz'/></joint></robot>", "'j'"),
    ("<robot name='r'><link", "boxes.urdf"),
])
def test_bad_models_raise_the_commands_error(tmp_path, binary, content, message):
    path = tmp_path / "boxes.urdf"
    if content is not None:
        path.write_text(content)
    with pytest.raises(urdfsnap.Error) as raised:
        urdfsnap.Robot(path)
    assert message in str(raised.value)
    cli = run_cli(binary, "render", path, "-o", tmp_path / "out.png")
    assert cli.returncode == 2
    assert cli.stderr.strip().endswith(str(raised.value))


def test_a_xacro_error_names_file_and_line(tmp_path):
    path = tmp_path / "bad.urdf.xacro"
    path.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">\n'
                    '  <xacro:property name="a" value="${1 +}"/>\n  <link name="${a}"/>\n</robot>\n')
    with pytest.raises(urdfsnap.Error, match="bad.urdf.xacro:"):
        urdfsnap.Robot(path)
    with pytest.raises(urdfsnap.Error):
        urdfsnap.xacro(path)


def test_xacro_arguments_reach_the_document(tmp_path):
    path = tmp_path / "arg.urdf.xacro"
    path.write_text('<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">\n'
                    '  <xacro:arg name="link" default="a"/>\n  <link name="$(arg link)"/>\n</robot>\n')
    assert urdfsnap.Robot(path).links == ["a"]
    assert urdfsnap.Robot(path, args={"link": "tool"}).links == ["tool"]
    assert urdfsnap.Robot(path, args={"link": 7}).links == ["7"]  # values as str() gives them
