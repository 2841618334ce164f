// DescribeRobotJson: every key of docs/info.schema.json for a robot with each joint type.
#include "model/robot_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_robots.h"

namespace urdfsnap::model {
namespace {

using nlohmann::json;

json Described(const char* urdf) {
  Warnings warnings;
  return json::parse(DescribeRobotJson(LoadRobot(urdf, "kinds.urdf", warnings)));
}

const json& Named(const json& list, const std::string& name) {
  for (const json& item : list) {
    if (item.value("name", "") == name) return item;
  }
  throw std::runtime_error("no " + name);
}

TEST(RobotJsonTest, NamesTheRobotAndItsRoot) {
  const json robot = Described(test::kEveryJointUrdf);
  EXPECT_EQ(robot["name"], "kinds");
  EXPECT_EQ(robot["source"], "kinds.urdf");
  EXPECT_EQ(robot["root"], "base");
  EXPECT_EQ(robot["links"].size(), 8u);
  EXPECT_EQ(robot["joints"].size(), 7u);
}

TEST(RobotJsonTest, JointsCarryEveryLimitOriginAndDefault) {
  const json joints = Described(test::kEveryJointUrdf)["joints"];
  const json& rev = Named(joints, "rev");
  EXPECT_EQ(rev["type"], "revolute");
  EXPECT_EQ(rev["parent"], "base");
  EXPECT_EQ(rev["child"], "a");
  EXPECT_EQ(rev["origin"]["xyz"], json::array({1, 0, 0}));
  EXPECT_EQ(rev["origin"]["rpy"], json::array({0, 0, 1.57079632679}));
  EXPECT_EQ(rev["axis"], json::array({0, 0, 1}));   // normalised from (0 0 2)
  EXPECT_EQ(rev["limits"], (json{{"lower", -1}, {"upper", 2}, {"velocity", 1}, {"effort", 1}}));
  EXPECT_EQ(rev["movable"], true);
  EXPECT_EQ(rev["default"], 0);
  EXPECT_TRUE(rev["mimic"].is_null());

  // 0 is outside [0.1, 0.5]: joint_state_publisher starts in the middle
  EXPECT_DOUBLE_EQ(Named(joints, "slide")["default"].get<double>(), 0.3);

  const json& spin = Named(joints, "spin");
  EXPECT_TRUE(spin["limits"].is_null());   // a continuous joint without <limit>
  const json rpy = spin["origin"]["rpy"];
  EXPECT_NEAR(rpy[0].get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(rpy[1].get<double>(), 0, 1e-12);
  EXPECT_NEAR(rpy[2].get<double>(), -0.6, 1e-12);

  const json& weld = Named(joints, "weld");
  EXPECT_TRUE(weld["axis"].is_null());
  EXPECT_EQ(weld["movable"], false);
  EXPECT_TRUE(weld["default"].is_null());
  EXPECT_NEAR(weld["origin"]["rpy"][1].get<double>(), 0.25, 1e-12);

  EXPECT_EQ(Named(joints, "follower")["mimic"],
            (json{{"joint", "rev"}, {"multiplier", -0.5}, {"offset", 0.1}}));
  EXPECT_TRUE(Named(joints, "free")["axis"].is_null());
}

TEST(RobotJsonTest, ContinuousJointWithALimitHasVelocityAndEffortOnly) {
  const json joints = Described(R"(<robot name="r"><link name="a"/><link name="b"/>
    <joint name="wheel" type="continuous"><parent link="a"/><child link="b"/>
      <limit effort="40" velocity="3.5"/></joint></robot>)")["joints"];
  EXPECT_EQ(joints[0]["limits"], (json{{"lower", nullptr}, {"upper", nullptr}, {"velocity", 3.5}, {"effort", 40}}));
}

TEST(RobotJsonTest, LinksAndTreeFollowTheTreeOrder) {
  const json robot = Described(R"(<robot name="r">
    <link name="base"><inertial><mass value="2.5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
      <visual><geometry><box size="1 1 1"/></geometry></visual></link>
    <link name="tip"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
    <joint name="j" type="fixed"><parent link="base"/><child link="tip"/></joint></robot>)");
  const json& base = robot["links"][0];
  EXPECT_EQ(base["name"], "base");
  EXPECT_TRUE(base["parent_joint"].is_null());
  EXPECT_EQ(base["child_joints"], json::array({"j"}));
  EXPECT_EQ(base["visuals"], 1);
  EXPECT_EQ(base["mass"], 2.5);
  const json& tip = robot["links"][1];
  EXPECT_EQ(tip["parent_joint"], "j");
  EXPECT_EQ(tip["collisions"], 1);
  EXPECT_TRUE(tip["mass"].is_null());
  EXPECT_EQ(robot["tree"], json::parse(R"([
    {"link": "base", "depth": 0, "parent_link": null, "joint": null},
    {"link": "tip", "depth": 1, "parent_link": "base", "joint": "j"}])"));
}

}  // namespace
}  // namespace urdfsnap::model
