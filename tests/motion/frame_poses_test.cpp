// Poses per frame on a small robot: interpolated trajectory joints, defaults for the others, mimic
// joints following, unknown joints ignored with one warning (located errors when strict), values
// drawn as recorded or clamped with one warning per joint.
#include "motion/frame_poses.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap::motion {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// joints: shoulder [-1, 1], elbow (continuous), finger [0, 0.04] with mimic finger2 = 2 * finger,
// a fixed tool joint
constexpr const char* kRobot = R"(<robot name="arm">
  <link name="base"/><link name="upper"/><link name="lower"/><link name="f1"/><link name="f2"/>
  <link name="tool"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="continuous"><parent link="upper"/><child link="lower"/></joint>
  <joint name="finger" type="prismatic"><parent link="lower"/><child link="f1"/>
    <limit lower="0" upper="0.04" effort="1" velocity="1"/></joint>
  <joint name="finger2" type="prismatic"><parent link="lower"/><child link="f2"/>
    <limit lower="0" upper="0.08" effort="1" velocity="1"/><mimic joint="finger" multiplier="2"/></joint>
  <joint name="tool_joint" type="fixed"><parent link="lower"/><child link="tool"/></joint>
</robot>)";

class FramePosesTest : public ::testing::Test {
 protected:
  Warnings load_warnings_;
  const model::Robot robot_ = model::LoadRobot(kRobot, "arm.urdf", load_warnings_);

  static Trajectory Wave() {
    Trajectory trajectory;
    trajectory.source = "wave.csv";
    trajectory.tracks = {{"elbow", {0, 2}, {0, 4}, "wave.csv:1"},
                         {"finger", {0, 1}, {0, 0.02}, "wave.csv:1"}};
    return trajectory;
  }
};

TEST_F(FramePosesTest, InterpolatesTheTrajectoryAndTakesDefaultsForTheRest) {
  Warnings warnings;
  const Trajectory wave = Wave();
  const FramePoses poses(robot_, wave, {{"shoulder", 0.5}, {"elbow", 9.0}}, {}, warnings);
  // shoulder from the defaults, elbow and finger interpolated (the trajectory wins over the
  // default for elbow), finger2 mimics finger, the fixed joint stays 0
  EXPECT_THAT(poses.At(0.5, warnings), ElementsAre(0.5, 1.0, 0.01, 0.02, 0.0));
  EXPECT_THAT(poses.At(5.0, warnings), ElementsAre(0.5, 4.0, 0.02, 0.04, 0.0));
  EXPECT_TRUE(warnings.empty()) << warnings.messages()[0];
}

TEST_F(FramePosesTest, JointsTheRobotLacksAreIgnoredWithOneWarning) {
  // a gripper's and a second robot's joints on the same topic
  Trajectory trajectory = Wave();
  trajectory.tracks.push_back({"gripper_left", {0, 1}, {0, 0.01}, "wave.csv:1"});
  trajectory.tracks.push_back({"other_arm", {0, 1}, {0, 1}, "wave.csv:1"});
  Warnings warnings;
  const FramePoses poses(robot_, trajectory, {}, {}, warnings);
  EXPECT_THAT(warnings.messages(),
              ElementsAre("wave.csv: joints robot 'arm' does not have are ignored: "
                          "'gripper_left', 'other_arm' (--strict-joints stops instead)"));
  EXPECT_THAT(poses.At(0.5, warnings), ElementsAre(0.0, 1.0, 0.01, 0.02, 0.0));
  EXPECT_EQ(warnings.messages().size(), 1u);

  // none of them the robot's: another robot's trajectory, an error at the first
  Trajectory other;
  other.tracks = {{"wheel", {0, 1}, {0, 1}, "other.csv:1"}};
  EXPECT_EQ(test::ErrorText([&] { FramePoses(robot_, other, {}, {}, warnings); }),
            "other.csv:1: robot 'arm' has no joint 'wheel'; its movable joints are: shoulder, "
            "elbow, finger");
}

TEST_F(FramePosesTest, StrictJointsLocateAnUnknownJointInTheTrajectory) {
  Trajectory trajectory = Wave();
  trajectory.tracks[1].joint = "fingr";
  trajectory.tracks[1].named_at = "wave.csv:1";
  Warnings warnings;
  EXPECT_EQ(test::ErrorText([&] {
              FramePoses(robot_, trajectory, {}, {.strict_joints = true}, warnings);
            }),
            "wave.csv:1: robot 'arm' has no joint 'fingr'; its movable joints are: shoulder, "
            "elbow, finger");
}

TEST_F(FramePosesTest, ValuesOutsideTheLimitsAreDrawnAsRecordedWithOneWarningPerJoint) {
  Trajectory trajectory;
  trajectory.source = "swing.csv";
  trajectory.tracks = {{"shoulder", {0, 1, 2, 3}, {0, 1.5, -2.5, 0}, "swing.csv:1"},
                       {"finger", {0, 1}, {0, 0.04}, "swing.csv:1"}};
  Warnings warnings;
  const FramePoses poses(robot_, trajectory, {}, {}, warnings);
  EXPECT_THAT(warnings.messages(),
              ElementsAre("joint 'shoulder': swing.csv takes it outside its limits, -1 to 1 rad, at "
                          "1 s, furthest to -2.5 rad at 2 s (1.5 rad beyond); drawn as recorded "
                          "(--clamp clamps it)"));
  EXPECT_DOUBLE_EQ(poses.At(2, warnings)[0], -2.5);
  EXPECT_DOUBLE_EQ(poses.At(1, warnings)[0], 1.5);
  EXPECT_EQ(warnings.messages().size(), 1u);
}

TEST_F(FramePosesTest, ClampTrajectoryClampsEveryFrameButWarnsOncePerJoint) {
  Trajectory trajectory;
  trajectory.source = "swing.csv";
  trajectory.tracks = {{"shoulder", {0, 1, 2, 3}, {0, 1.5, -2.5, 0}, "swing.csv:1"}};
  Warnings warnings;
  const FramePoses poses(robot_, trajectory, {}, {.clamp_trajectory = true}, warnings);
  EXPECT_THAT(warnings.messages(),
              ElementsAre("joint 'shoulder': swing.csv takes it outside its limits, -1 to 1 rad, at "
                          "1 s, furthest to -2.5 rad at 2 s (1.5 rad beyond); clamped in every frame as "
                          "joint_state_publisher's slider would"));
  for (double t = 0; t <= 3; t += 0.1) {
    const double shoulder = poses.At(t, warnings)[0];
    EXPECT_GE(shoulder, -1.0);
    EXPECT_LE(shoulder, 1.0);
  }
  EXPECT_EQ(warnings.messages().size(), 1u);
}

TEST_F(FramePosesTest, DefaultsAreClampedAsRenderClampsThemUnlessTold) {
  const Trajectory wave = Wave();
  Warnings warnings;
  const FramePoses clamped(robot_, wave, {{"shoulder", 5.0}}, {}, warnings);
  EXPECT_EQ(clamped.At(0, warnings)[0], 1.0);
  EXPECT_THAT(warnings.messages(), ElementsAre(HasSubstr("joint 'shoulder': 5 rad is outside its "
                                                         "limits, -1 to 1 rad; clamped to 1 rad")));
  Warnings unclamped_warnings;
  const FramePoses unclamped(robot_, wave, {{"shoulder", 5.0}}, {.clamp_defaults = false},
                             unclamped_warnings);
  EXPECT_EQ(unclamped.At(0, unclamped_warnings)[0], 5.0);
  EXPECT_TRUE(unclamped_warnings.empty());
}

TEST_F(FramePosesTest, AFixedJointInTheTrajectoryWarnsOnceAcrossFrames) {
  Trajectory trajectory;
  trajectory.tracks = {{"tool_joint", {0, 1}, {0, 1}, "t.csv:1"}};
  Warnings warnings;
  const FramePoses poses(robot_, trajectory, {}, {}, warnings);
  for (double t = 0; t <= 1; t += 0.25) poses.At(t, warnings);
  ASSERT_EQ(warnings.messages().size(), 1u);
  EXPECT_THAT(warnings.messages()[0], HasSubstr("joint 'tool_joint' is fixed"));
}

}  // namespace
}  // namespace urdfsnap::motion
