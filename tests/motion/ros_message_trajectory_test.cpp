// ROS message trajectories in YAML and JSON as MoveIt and `ros2 topic echo` write them, and the
// located errors for bad ones.
#include "motion/ros_message_trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap::motion {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A JointTrajectory exactly as `ros2 topic echo --once /arm_controller/joint_trajectory` prints it.
constexpr const char* kEchoedJointTrajectory = R"(header:
  stamp:
    sec: 0
    nanosec: 0
  frame_id: ''
joint_names:
- shoulder
- elbow
points:
- positions:
  - 0.0
  - 0.0
  velocities: []
  accelerations: []
  effort: []
  time_from_start:
    sec: 0
    nanosec: 0
- positions:
  - 0.5
  - -1.0
  velocities: []
  accelerations: []
  effort: []
  time_from_start:
    sec: 1
    nanosec: 500000000
---
)";

TEST(RosMessageTrajectoryTest, ReadsAnEchoedJointTrajectory) {
  const Trajectory trajectory = ParseRosMessageTrajectory(kEchoedJointTrajectory, "plan.yaml");
  ASSERT_EQ(trajectory.tracks.size(), 2u);
  EXPECT_EQ(trajectory.tracks[0].joint, "shoulder");
  EXPECT_THAT(trajectory.tracks[0].times, ElementsAre(0.0, 1.5));
  EXPECT_THAT(trajectory.tracks[0].positions, ElementsAre(0.0, 0.5));
  EXPECT_THAT(trajectory.tracks[1].positions, ElementsAre(0.0, -1.0));
  EXPECT_EQ(trajectory.tracks[1].named_at, "plan.yaml:10");  // the first point naming it
}

struct TimesCase {
  const char* name;
  const char* text;
  std::vector<double> times;
};

class TimesTest : public ::testing::TestWithParam<TimesCase> {};

TEST_P(TimesTest, AreTheSampleTimes) {
  EXPECT_EQ(ParseRosMessageTrajectory(GetParam().text, "t.yaml").tracks[0].times, GetParam().times);
}

INSTANTIATE_TEST_SUITE_P(
    Messages, TimesTest,
    ::testing::Values(
        // time_from_start counts from 0 and may be seconds
        TimesCase{"seconds",
                  "joint_names: [elbow]\npoints:\n- {positions: [1], time_from_start: 0.5}\n"
                  "- {positions: [2], time_from_start: 2}\n",
                  {0.5, 2.0}},
        // a list of JointStates with ROS 1's stamp fields
        TimesCase{"ros1_list",
                  "- {header: {stamp: {secs: 5, nsecs: 0}}, name: [a], position: [1]}\n"
                  "- {header: {stamp: {secs: 6, nsecs: 0}}, name: [a], position: [2]}\n",
                  {0.0, 1.0}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(RosMessageTrajectoryTest, ReadsJsonWithLineNumbers) {
  const char* json = R"({
  "joint_names": ["elbow"],
  "points": [
    {"positions": [1.0], "time_from_start": {"sec": 0, "nanosec": 0}},
    {"positions": [2.0], "time_from_start": {"sec": 0, "nanosec": 250000000}}
  ]
})";
  const Trajectory trajectory = ParseRosMessageTrajectory(json, "plan.json");
  EXPECT_THAT(trajectory.tracks[0].times, ElementsAre(0.0, 0.25));
  EXPECT_EQ(trajectory.tracks[0].named_at, "plan.json:4");
}

TEST(RosMessageTrajectoryTest, ReadsMoveItRobotAndDisplayTrajectories) {
  const Trajectory robot_trajectory = ParseRosMessageTrajectory(
      "joint_trajectory:\n  joint_names: [a]\n  points:\n"
      "  - {positions: [1], time_from_start: {sec: 1, nanosec: 0}}\n"
      "multi_dof_joint_trajectory: {joint_names: [], points: []}\n",
      "robot.yaml");
  EXPECT_THAT(robot_trajectory.tracks[0].times, ElementsAre(1.0));
  // RViz plays a DisplayTrajectory's segments one after the other; a segment starting where the
  // previous ended does not repeat that instant
  const Trajectory display = ParseRosMessageTrajectory(
      "model_id: mrm\ntrajectory:\n"
      "- joint_trajectory: {joint_names: [a], points: [{positions: [0], time_from_start: 0},\n"
      "                                                {positions: [1], time_from_start: 1}]}\n"
      "- joint_trajectory: {joint_names: [a], points: [{positions: [1], time_from_start: 0},\n"
      "                                                {positions: [3], time_from_start: 2}]}\n",
      "display.yaml");
  EXPECT_THAT(display.tracks[0].times, ElementsAre(0.0, 1.0, 3.0));
  EXPECT_THAT(display.tracks[0].positions, ElementsAre(0.0, 1.0, 3.0));
}

// JointStates as `ros2 topic echo /joint_states` prints them (block style, and flow style as
// `--flow-style` does), with a gripper's message between them.
constexpr const char* kEchoedJointStates = R"(header:
  stamp:
    sec: 1700000000
    nanosec: 900000000
  frame_id: ''
name:
- shoulder
- elbow
position:
- 0.1
- 0.2
velocity: []
effort: []
---
header:
  stamp:
    sec: 1700000001
    nanosec: 100000000
  frame_id: ''
name: [finger]
position: [0.01]
velocity: []
effort: []
---
{header: {stamp: {sec: 1700000001, nanosec: 400000000}, frame_id: ''},
 name: [shoulder, elbow], position: [0.3, 0.4], velocity: [], effort: []}
---
)";

TEST(RosMessageTrajectoryTest, ReadsAnEchoedJointStateStream) {
  const Trajectory trajectory = ParseRosMessageTrajectory(kEchoedJointStates, "states.yaml");
  ASSERT_EQ(trajectory.tracks.size(), 3u);
  // times from the first message's stamp
  EXPECT_THAT(trajectory.tracks[0].times, ElementsAre(0.0, ::testing::DoubleNear(0.5, 1e-12)));
  EXPECT_THAT(trajectory.tracks[1].positions, ElementsAre(0.2, 0.4));
  EXPECT_EQ(trajectory.tracks[2].joint, "finger");
  EXPECT_THAT(trajectory.tracks[2].times, ElementsAre(::testing::DoubleNear(0.2, 1e-12)));
  EXPECT_EQ(trajectory.tracks[2].named_at, "states.yaml:15");
}

struct BadMessages {
  const char* name;
  const char* text;
  const char* error;
};

class BadMessagesTest : public ::testing::TestWithParam<BadMessages> {};

TEST_P(BadMessagesTest, IsOneLocatedError) {
  EXPECT_THAT(test::ErrorText([] { ParseRosMessageTrajectory(GetParam().text, "bad.yaml"); }),
              HasSubstr(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Messages, BadMessagesTest,
    ::testing::Values(
        BadMessages{"empty", "", "bad.yaml: no trajectory or JointState message"},
        BadMessages{"bad_yaml", "a: [1,\n", "bad.yaml:2: bad YAML: "},
        BadMessages{"bad_yaml_second_document",
                    "{header: {stamp: {sec: 1, nanosec: 0}}, name: [a], position: [1]}\n---\n"
                    "header: {stamp: {sec: 2, nanosec: 0}}\nname: [a\n",
                    "bad.yaml:5: bad YAML"},
        BadMessages{"other_message", "data: hello\n", "bad.yaml:1: expected a JointTrajectory"},
        BadMessages{"no_points", "joint_names: [a]\n",
                    "bad.yaml:1: the JointTrajectory has no 'points'"},
        BadMessages{"no_time", "joint_names: [a]\npoints:\n- positions: [1]\n",
                    "bad.yaml:3: the point has no 'time_from_start'"},
        BadMessages{"nan_position",
                    "joint_names: [a]\npoints:\n- {positions: [.nan], time_from_start: 0}\n",
                    "bad.yaml:3: positions: expected a finite number, got '.nan'"},
        BadMessages{"count_mismatch",
                    "joint_names: [a, b]\npoints:\n- {positions: [1], time_from_start: 0}\n",
                    "bad.yaml:3: 2 names but 1 positions"},
        BadMessages{"time_not_increasing",
                    "joint_names: [a]\npoints:\n- {positions: [1], time_from_start: 1}\n"
                    "- {positions: [2], time_from_start: 1}\n",
                    "bad.yaml:4: joint 'a' at 1 s is not after its previous sample at 1 s"},
        BadMessages{"bad_nanosec",
                    "joint_names: [a]\npoints:\n- {positions: [1], time_from_start: {sec: 0, "
                    "nanosec: 2000000000}}\n",
                    "bad.yaml:3: time_from_start: expected whole seconds and 0 <= nanosec < 1e9"},
        BadMessages{"empty_points", "joint_names: [a]\npoints: []\n",
                    "bad.yaml: no joint positions in it: an empty trajectory"},
        BadMessages{"two_trajectories",
                    "joint_names: [a]\npoints: [{positions: [1], time_from_start: 0}]\n---\n"
                    "joint_names: [a]\npoints: [{positions: [1], time_from_start: 0}]\n",
                    "bad.yaml:4: a second trajectory; urdfsnap animates one"},
        BadMessages{"state_without_header", "name: [a]\nposition: [1]\n",
                    "bad.yaml:1: the JointState has no 'header'"},
        BadMessages{"state_going_back",
                    "{header: {stamp: {sec: 2, nanosec: 0}}, name: [a], position: [1]}\n---\n"
                    "{header: {stamp: {sec: 1, nanosec: 0}}, name: [a], position: [2]}\n",
                    "bad.yaml:3: joint 'a' at -1 s is not after its previous sample at 0 s"},
        BadMessages{"joint_twice",
                    "{header: {stamp: {sec: 2, nanosec: 0}}, name: [a, a], position: [1, 2]}\n",
                    "bad.yaml:1: joint 'a' is named twice"},
        BadMessages{"names_not_a_list",
                    "{header: {stamp: {sec: 2, nanosec: 0}}, name: a, position: [1]}\n",
                    "bad.yaml:1: 'name' is not a list of names"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace urdfsnap::motion
