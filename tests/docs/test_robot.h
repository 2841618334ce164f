// A small robot for the docs page tests with every kind of joint and names that need escaping.
#pragma once

namespace urdfsnap::docs {

inline constexpr const char* kGripperUrdf = R"(<?xml version="1.0"?>
<robot name="grip&amp;bot">
  <link name="base"><visual><geometry><box size="0.4 0.3 0.1"/></geometry></visual>
    <collision><geometry><box size="0.4 0.3 0.1"/></geometry></collision>
    <inertial><mass value="2.5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
  <joint name="turn" type="continuous"><parent link="base"/><child link="column"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 0 1"/></joint>
  <link name="column"><visual><geometry><cylinder radius="0.05" length="0.5"/></geometry></visual></link>
  <joint name="lift" type="prismatic"><parent link="column"/><child link="carriage"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/><limit lower="-0.2" upper="0.1" effort="1" velocity="1"/></joint>
  <link name="carriage"><visual><geometry><mesh filename="package://grip/meshes/carriage.stl" scale="0.001 0.001 0.001"/></geometry></visual></link>
  <joint name="wrist" type="revolute"><parent link="carriage"/><child link="hand"/>
    <axis xyz="1 0 0"/><limit lower="0.5" upper="1.5" effort="1" velocity="1"/></joint>
  <link name="hand"><visual><geometry><sphere radius="0.04"/></geometry></visual></link>
  <joint name="finger_left" type="revolute"><parent link="hand"/><child link="left"/>
    <axis xyz="0 1 0"/><limit lower="-0.5" upper="0.5" effort="1" velocity="1"/></joint>
  <link name="left"/>
  <joint name="finger_right" type="revolute"><parent link="hand"/><child link="a&lt;b&gt;|*_x_"/>
    <axis xyz="0 1 0"/><limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>
    <mimic joint="finger_left" multiplier="-1" offset="0.1"/></joint>
  <link name="a&lt;b&gt;|*_x_"/>
  <joint name="camera_mount" type="fixed"><parent link="base"/><child link="camera"/></joint>
  <link name="camera"/>
</robot>)";

}  // namespace urdfsnap::docs
