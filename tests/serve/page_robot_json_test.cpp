// /api/robot's joint table follows joint_state_publisher_gui: movable joints only, ±π for
// continuous joints, its default value, mimic joints marked.
#include "serve/page_robot_json.h"

#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace urdfsnap::serve {
namespace {

constexpr const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="rig">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/><link name="d"/><link name="e"/>
  <joint name="fixed" type="fixed"><parent link="base"/><child link="a"/></joint>
  <joint name="spin" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint>
  <joint name="lift" type="prismatic"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
    <limit lower="0.2" upper="0.6" effort="1" velocity="1"/></joint>
  <joint name="tilt" type="revolute"><parent link="c"/><child link="d"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="2" effort="1" velocity="1"/></joint>
  <joint name="tilt_copy" type="revolute"><parent link="d"/><child link="e"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="4" effort="1" velocity="1"/>
    <mimic joint="tilt" multiplier="2" offset="0.5"/></joint>
</robot>)";

TEST(PageRobotJson, JointStatePublisherRules) {
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(kUrdf, "rig.urdf", warnings);
  const auto json = nlohmann::json::parse(PageRobotJson(robot, {"a warning"}));
  EXPECT_EQ(json["name"], "rig");
  EXPECT_EQ(json["warnings"], nlohmann::json::array({"a warning"}));
  const auto& joints = json["joints"];
  ASSERT_EQ(joints.size(), 4u);  // not the fixed joint
  EXPECT_EQ(joints[0]["name"], "spin");
  EXPECT_EQ(joints[0]["type"], "continuous");
  EXPECT_DOUBLE_EQ(joints[0]["lower"], -std::numbers::pi);
  EXPECT_DOUBLE_EQ(joints[0]["upper"], std::numbers::pi);
  EXPECT_DOUBLE_EQ(joints[0]["default"], 0);
  EXPECT_TRUE(joints[0]["mimic"].is_null());
  // 0 outside the limits: the middle, as joint_state_publisher starts it
  EXPECT_EQ(joints[1]["name"], "lift");
  EXPECT_DOUBLE_EQ(joints[1]["lower"], 0.2);
  EXPECT_DOUBLE_EQ(joints[1]["upper"], 0.6);
  EXPECT_DOUBLE_EQ(joints[1]["default"], 0.4);
  EXPECT_DOUBLE_EQ(joints[2]["default"], 0);
  // the mimic joint follows its leader: default 2 * 0 + 0.5
  EXPECT_EQ(joints[3]["name"], "tilt_copy");
  EXPECT_EQ(joints[3]["mimic"]["joint"], "tilt");
  EXPECT_DOUBLE_EQ(joints[3]["mimic"]["multiplier"], 2);
  EXPECT_DOUBLE_EQ(joints[3]["mimic"]["offset"], 0.5);
  EXPECT_DOUBLE_EQ(joints[3]["default"], 0.5);
}

}  // namespace
}  // namespace urdfsnap::serve
