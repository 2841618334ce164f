// The frames of an animation: counts for the rule k = 0 ... floor(T * fps), speed, tables
// without times, durations, the turntable's yaw, and refused arguments.
#include "motion/frame_plan.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "support/error_text.h"

namespace urdfsnap::motion {
namespace {

using ::testing::HasSubstr;

Trajectory EndingAt(double end, TimeBase time_base = TimeBase::kSeconds) {
  Trajectory trajectory;
  trajectory.time_base = time_base;
  trajectory.tracks = {{"a", {0, end}, {0, 1}, ""}};
  return trajectory;
}

TEST(FramePlanTest, FramesAtKOverFpsUpToTheEnd) {
  const FramePlan plan = PlanFrames(EndingAt(2.0), 10, 1);
  EXPECT_EQ(plan.frame_count, 21);  // 0, 0.1, ..., 2.0
  EXPECT_DOUBLE_EQ(plan.Seconds(20), 2.0);
  EXPECT_DOUBLE_EQ(plan.TrajectoryTime(20), 2.0);
  // 1.99 s at 10 frames/s: the last frame is at 1.9 s
  EXPECT_EQ(PlanFrames(EndingAt(1.99), 10, 1).frame_count, 20);
  // 0.3 * 30 is 8.999999999999998 in binary: still 10 frames
  EXPECT_EQ(PlanFrames(EndingAt(0.3), 30, 1).frame_count, 10);
}

TEST(FramePlanTest, SpeedScalesTheTrajectoryTime) {
  const FramePlan plan = PlanFrames(EndingAt(4.0), 25, 2);
  EXPECT_EQ(plan.frame_count, 51);  // 2 s of animation
  EXPECT_DOUBLE_EQ(plan.TrajectoryTime(50), 4.0);
  EXPECT_EQ(PlanFrames(EndingAt(1.0), 10, 0.5).frame_count, 21);
}

TEST(FramePlanTest, ATableWithoutTimesShowsOneRowPerFrame) {
  const FramePlan plan = PlanFrames(EndingAt(9, TimeBase::kRows), 30, 1);
  EXPECT_EQ(plan.frame_count, 10);
  EXPECT_DOUBLE_EQ(plan.TrajectoryTime(7), 7.0);
  EXPECT_EQ(PlanFrames(EndingAt(9, TimeBase::kRows), 30, 3).frame_count, 4);
}

TEST(FramePlanTest, ADurationReplacesTheTrajectoryLength) {
  EXPECT_EQ(PlanFrames(EndingAt(2.0), 10, 1, 5.0).frame_count, 51);
  const FramePlan still = PlanStill(4.0, 30);
  EXPECT_EQ(still.frame_count, 121);
  EXPECT_DOUBLE_EQ(still.TrajectoryTime(100), 0.0);
  // one instant is one frame
  EXPECT_EQ(PlanFrames(EndingAt(0.0), 30, 1).frame_count, 1);
}

TEST(FramePlanTest, TurntableTurnsOnceWithoutRepeatingTheFirstFrame) {
  const FramePlan plan = PlanStill(1.0, 4);  // 5 frames
  EXPECT_DOUBLE_EQ(plan.TurntableYaw(0, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(plan.TurntableYaw(1, 0.5), 0.5 + 2 * std::numbers::pi / 5);
  EXPECT_LT(plan.TurntableYaw(4, 0.0), 2 * std::numbers::pi);
}

TEST(FramePlanTest, RefusesBadArgumentsAndEndlessAnimations) {
  using test::ErrorText;
  EXPECT_THAT(
      ErrorText([] { PlanFrames(EndingAt(1), 0, 1); }),
      HasSubstr("the frame rate (frames per second) must be a positive number up to 1000, got 0"));
  EXPECT_THAT(ErrorText([] { PlanFrames(EndingAt(1), 5000, 1); }), HasSubstr("got 5000"));
  EXPECT_THAT(ErrorText([] { PlanFrames(EndingAt(1), 30, -1); }),
              HasSubstr("the playback speed must be a positive number, got -1"));
  EXPECT_THAT(ErrorText([] { PlanFrames(EndingAt(1), 30, std::nan("")); }), HasSubstr("speed"));
  EXPECT_THAT(ErrorText([] { PlanStill(0, 30); }), HasSubstr("the duration (seconds) must be"));
  EXPECT_THAT(ErrorText([] { PlanFrames(EndingAt(1.7e9), 30, 1); }),
              HasSubstr("frames (1.7e+09 s at 30 frames/s), more than urdfsnap's limit"));
}

}  // namespace
}  // namespace urdfsnap::motion
