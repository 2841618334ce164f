// The small robot the fuzz targets pose: every kind of joint a value can meet (revolute with
// limits, prismatic, continuous mimic, fixed).
#pragma once

namespace urdfsnap::fuzz {

inline constexpr const char* kFuzzRobot = R"(<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="a"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="slide" type="prismatic"><parent link="a"/><child link="b"/>
    <limit lower="0.2" upper="0.5" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="b"/><child link="c"/>
    <mimic joint="shoulder" multiplier="-2" offset="0.1"/></joint>
  <joint name="weld" type="fixed"><parent link="c"/><child link="d"/></joint>
</robot>)";

}  // namespace urdfsnap::fuzz
