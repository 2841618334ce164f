// Linear interpolation and held samples of one joint, and the trajectory's end time.
#include "motion/trajectory.h"

#include <gtest/gtest.h>

namespace urdfsnap::motion {
namespace {

TEST(TrajectoryTest, InterpolatesLinearlyAndHoldsTheEnds) {
  const JointTrack track{"elbow", {0.5, 1.5, 2.0}, {1.0, 3.0, -1.0}, "t.csv:2"};
  EXPECT_DOUBLE_EQ(PositionAt(track, -1.0), 1.0);  // before the first sample: the first
  EXPECT_DOUBLE_EQ(PositionAt(track, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.5), 3.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.75), 1.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 2.0), -1.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 9.0), -1.0);  // after the last: the last
}

TEST(TrajectoryTest, ARecordingHoldsEachSampleUntilTheNext) {
  const JointTrack track{"elbow", {0.5, 1.5, 2.0}, {1.0, 3.0, -1.0}, "bag.mcap"};
  EXPECT_DOUBLE_EQ(PositionAt(track, -1.0, Between::kHold), 1.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.0, Between::kHold), 1.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.5, Between::kHold), 3.0);
  // a frame time rounded just below a stamp is at it
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.5 - 1e-12, Between::kHold), 3.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 1.99, Between::kHold), 3.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 2.0 - 1e-12, Between::kHold), -1.0);
  EXPECT_DOUBLE_EQ(PositionAt(track, 9.0, Between::kHold), -1.0);
}

TEST(TrajectoryTest, OneSampleIsAStillPose) {
  const JointTrack track{"elbow", {0.0}, {0.7}, ""};
  EXPECT_DOUBLE_EQ(PositionAt(track, 0.0), 0.7);
  EXPECT_DOUBLE_EQ(PositionAt(track, 3.0), 0.7);
}

TEST(TrajectoryTest, EndTimeIsTheLatestSampleOfAnyJoint) {
  Trajectory trajectory;
  trajectory.tracks = {{"a", {0, 1}, {0, 0}, ""}, {"b", {0.5, 2.5}, {0, 0}, ""}};
  EXPECT_DOUBLE_EQ(trajectory.EndTime(), 2.5);
}

}  // namespace
}  // namespace urdfsnap::motion
