// The TF display's frames of a recording: the robot's links with their parents, then the bag's
// other frames (odom above the root, a sensor frame below a link, a map above odom) placed through
// TF from the links' scene poses, frames TF does not connect left out.
#include "motion/tf_display_frames.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace urdfsnap::motion {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr const char* kRobot = R"(<robot name="rover">
  <link name="base_link"/><link name="mast"/>
  <joint name="mast_joint" type="fixed"><parent link="base_link"/><child link="mast"/>
    <origin xyz="0 0 1"/></joint>
</robot>)";

Eigen::Isometry3d At(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

// map -> odom static; odom -> base_link moving 1 m along +x from stamp 100 s to 101 s; mast ->
// camera static 0.1 m up; an unconnected world -> elsewhere
std::shared_ptr<const tf::TfBuffer> Drive() {
  auto buffer = std::make_shared<tf::TfBuffer>();
  const Eigen::Quaterniond identity = Eigen::Quaterniond::Identity();
  buffer->Add({"map", "odom", 0, {5, 0, 0}, identity}, true, "static");
  buffer->Add({"odom", "base_link", 100'000'000'000, {0, 0, 0}, identity}, false, "drive");
  buffer->Add({"odom", "base_link", 101'000'000'000, {1, 0, 0}, identity}, false, "drive");
  buffer->Add({"mast", "camera", 0, {0, 0, 0.1}, identity}, true, "static");
  buffer->Add({"world", "elsewhere", 0, {0, 0, 0}, identity}, true, "static");
  return buffer;
}

TEST(TfDisplayFramesTest, TheLinksThenTheBagsOtherFramesWithTheirParents) {
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(kRobot, "rover.urdf", warnings);
  const TfDisplayFrames frames(robot, Drive(), 100.0, "run.mcap");
  EXPECT_THAT(frames.names(), ElementsAre("base_link", "mast", "map", "odom", "camera"));
  // base_link's arrow points at odom (its TF parent), odom's at map, the camera's at the mast
  EXPECT_THAT(frames.parents(), ElementsAre(3, 0, -1, 2, 1));
}

TEST(TfDisplayFramesTest, OtherFramesArePlacedFromTheLinksScenePoses) {
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(kRobot, "rover.urdf", warnings);
  const TfDisplayFrames frames(robot, Drive(), 100.0, "run.mcap");
  // the robot drawn from base_link 2 m up in the scene, at trajectory time 0.5 (base_link 0.5 m
  // along odom's x)
  const std::vector<Eigen::Isometry3d> X_ST = frames.Poses({At(0, 0, 2), At(0, 0, 3)}, 0.5, warnings);
  ASSERT_EQ(X_ST.size(), 5u);
  EXPECT_TRUE(X_ST[1].translation().isApprox(Eigen::Vector3d(0, 0, 3)));
  EXPECT_TRUE(X_ST[2].translation().isApprox(Eigen::Vector3d(-5.5, 0, 2)));   // map
  EXPECT_TRUE(X_ST[3].translation().isApprox(Eigen::Vector3d(-0.5, 0, 2)));   // odom
  EXPECT_TRUE(X_ST[4].translation().isApprox(Eigen::Vector3d(0, 0, 3.1)));    // camera
  EXPECT_TRUE(warnings.empty());
  frames.Poses({At(0, 0, 0), At(0, 0, 1)}, 5, warnings);
  EXPECT_THAT(warnings.messages(), ElementsAre(HasSubstr("run.mcap: the TF display's frames are not all recorded")));
}

TEST(TfDisplayFramesTest, WithoutTheRobotInTfOnlyItsLinksAreShown) {
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(kRobot, "rover.urdf", warnings);
  auto buffer = std::make_shared<tf::TfBuffer>();
  buffer->Add({"world", "elsewhere", 0, {0, 0, 0}, Eigen::Quaterniond::Identity()}, true, "static");
  const TfDisplayFrames frames(robot, buffer, 0, "run.mcap");
  EXPECT_THAT(frames.names(), ElementsAre("base_link", "mast"));
  EXPECT_THAT(frames.parents(), ElementsAre(-1, 0));
}

}  // namespace
}  // namespace urdfsnap::motion
