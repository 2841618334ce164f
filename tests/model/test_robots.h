// Small robots inline for the model tests and the FK benchmark (MuJoCo-style raw strings).
#pragma once

namespace urdfsnap::model::test {

// The sample mrm manipulator (models/mrm_description/urdf/mrm.urdf) without its visuals' details:
// revolute joints about z, y, y, y, z at heights 0.5, 0.4, 0.8, 0.8, 0.8, limits +-3.14.
inline constexpr const char* kMrmUrdf = R"(<?xml version="1.0"?>
<robot name="mrm">
  <link name="base_link">
    <visual><geometry><box size="1 1 1"/></geometry></visual>
  </link>
  <joint name="base_link__link_01" type="revolute">
    <axis xyz="0 0 1"/>
    <limit effort="1000.0" lower="-3.14" upper="3.14" velocity="0.5"/>
    <origin rpy="0 0 0" xyz="0 0 0.5"/>
    <parent link="base_link"/>
    <child link="link_01"/>
  </joint>
  <link name="link_01">
    <visual>
      <origin rpy="0 0 0" xyz="0 0 0.2"/>
      <geometry><cylinder radius="0.35" length="0.4"/></geometry>
    </visual>
  </link>
  <joint name="link_01__link_02" type="revolute">
    <axis xyz="0 1 0"/>
    <limit effort="1000.0" lower="-3.14" upper="3.14" velocity="0.5"/>
    <origin rpy="0 0 0" xyz="0 0 0.4"/>
    <parent link="link_01"/>
    <child link="link_02"/>
  </joint>
  <link name="link_02"/>
  <joint name="link_02__link_03" type="revolute">
    <axis xyz="0 1 0"/>
    <limit effort="1000.0" lower="-3.14" upper="3.14" velocity="0.5"/>
    <origin rpy="0 0 0" xyz="0 0 0.8"/>
    <parent link="link_02"/>
    <child link="link_03"/>
  </joint>
  <link name="link_03"/>
  <joint name="link_03__link_04" type="revolute">
    <axis xyz="0 1 0"/>
    <limit effort="1000.0" lower="-3.14" upper="3.14" velocity="0.5"/>
    <origin rpy="0 0 0" xyz="0 0 0.8"/>
    <parent link="link_03"/>
    <child link="link_04"/>
  </joint>
  <link name="link_04"/>
  <joint name="link_04__link_05" type="revolute">
    <axis xyz="0 0 1"/>
    <limit effort="1000.0" lower="-3.14" upper="3.14" velocity="0.5"/>
    <origin rpy="0 0 0" xyz="0 0 0.8"/>
    <parent link="link_04"/>
    <child link="link_05"/>
  </joint>
  <link name="link_05"/>
</robot>
)";

// One joint of every type, a mimic joint and a prismatic joint whose limits exclude 0.
inline constexpr const char* kEveryJointUrdf = R"(<robot name="kinds">
  <link name="base"/>
  <joint name="rev" type="revolute">
    <parent link="base"/><child link="a"/>
    <origin xyz="1 0 0" rpy="0 0 1.5707963267948966"/>
    <axis xyz="0 0 2"/>
    <limit lower="-1" upper="2" effort="1" velocity="1"/>
  </joint>
  <link name="a"/>
  <joint name="slide" type="prismatic">
    <parent link="a"/><child link="b"/>
    <origin xyz="0 0 1"/>
    <axis xyz="1 0 0"/>
    <limit lower="0.1" upper="0.5" effort="1" velocity="1"/>
  </joint>
  <link name="b"/>
  <joint name="spin" type="continuous">
    <parent link="b"/><child link="c"/>
    <origin xyz="0.1 0.2 0.3" rpy="0.3 0 -0.6"/>
    <axis xyz="0 0.7071 0.7071"/>
  </joint>
  <link name="c"/>
  <joint name="weld" type="fixed">
    <parent link="c"/><child link="d"/>
    <origin xyz="0 0 0.5" rpy="0 0.25 0"/>
  </joint>
  <link name="d"/>
  <joint name="follower" type="revolute">
    <parent link="base"/><child link="e"/>
    <axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/>
    <mimic joint="rev" multiplier="-0.5" offset="0.1"/>
  </joint>
  <link name="e"/>
  <joint name="free" type="floating">
    <parent link="base"/><child link="f"/>
    <origin xyz="0 0 2"/>
  </joint>
  <link name="f"/>
  <joint name="plane" type="planar">
    <parent link="base"/><child link="g"/>
    <axis xyz="0 0 1"/>
  </joint>
  <link name="g"/>
</robot>
)";

}  // namespace urdfsnap::model::test
