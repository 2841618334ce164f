// Generator of synthetic xacro documents.
#include "synthetic_xacro.h"

namespace urdfsnap::bench {

std::string SyntheticXacro(int calls) {
  std::string text = R"(<?xml version="1.0"?>
<robot name="synthetic" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="seg_len" value="0.1"/>
  <xacro:property name="seg_mass" value="0.5"/>
  <xacro:macro name="segment" params="index parent *origin">
    <link name="link_${index}">
      <visual>
        <geometry>
          <cylinder radius="${0.02 + index * 1e-5}" length="${seg_len}"/>
        </geometry>
      </visual>
      <inertial>
        <mass value="${seg_mass}"/>
        <inertia ixx="${seg_mass * seg_len ** 2 / 12}" ixy="0" ixz="0" iyy="${seg_mass * seg_len ** 2 / 12}" iyz="0" izz="${seg_mass * 0.02 ** 2 / 2}"/>
      </inertial>
    </link>
    <joint name="joint_${index}" type="revolute">
      <parent link="${parent}"/>
      <child link="link_${index}"/>
      <xacro:insert_block name="origin"/>
      <limit effort="10" lower="-1.57" upper="1.57" velocity="1"/>
    </joint>
  </xacro:macro>
  <link name="link_0"/>
)";
  for (int k = 1; k <= calls; ++k) {
    text += "  <xacro:segment index=\"" + std::to_string(k) + "\" parent=\"link_" + std::to_string(k - 1) +
            "\">\n    <origin xyz=\"0 0 ${seg_len}\" rpy=\"0 0 ${" + std::to_string(k % 7) + " * 0.1}\"/>\n"
            "  </xacro:segment>\n";
  }
  return text + "</robot>\n";
}

}  // namespace urdfsnap::bench
