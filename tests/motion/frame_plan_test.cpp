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

TEST(FramePlanTest, AWindowPlaysPartOfTheTrajectoryFromItsStart) {
  // 10 s, from 2.5 s to 4 s at 10 frames/s: 16 frames, frame k at 2.5 + k / 10
  const FramePlan plan = PlanFrames(EndingAt(10.0), 10, 1, {}, {2.5, 4.0});
  EXPECT_EQ(plan.frame_count, 16);
  EXPECT_DOUBLE_EQ(plan.TrajectoryTime(0), 2.5);
  EXPECT_DOUBLE_EQ(plan.TrajectoryTime(15), 4.0);
  EXPECT_DOUBLE_EQ(plan.Seconds(15), 1.5);
  EXPECT_EQ(PlanFrames(EndingAt(10.0), 10, 2, {}, {8.0, {}}).frame_count, 11);  // 2 s at speed 2
  EXPECT_THAT(test::ErrorText([] { PlanFrames(EndingAt(10.0), 10, 1, {}, {4.0, 4.0}); }),
              HasSubstr("--end 4 s is not after the start at 4 s"));
  EXPECT_THAT(test::ErrorText([] { PlanFrames(EndingAt(10.0), 10, 1, {}, {12.0, {}}); }),
              HasSubstr("--start 12 s is outside"));
  EXPECT_THAT(test::ErrorText([] { PlanFrames(EndingAt(9, TimeBase::kRows), 10, 1, {}, {1.0, {}}); }),
              HasSubstr("a table without a time column"));
}

TEST(FramePlanTest, StampsNameTimesOfStampedTrajectories) {
  Trajectory stamped = EndingAt(10.0);
  stamped.stamp_at_zero = 1700000000.0;
  EXPECT_DOUBLE_EQ(TrajectorySeconds(stamped, 1700000002.5, "--start"), 2.5);
  EXPECT_DOUBLE_EQ(TrajectorySeconds(stamped, 2.5, "--start"), 2.5);
  Trajectory plan = EndingAt(10.0);
  plan.source = "plan.yaml";
  EXPECT_THAT(test::ErrorText([&] { TrajectorySeconds(plan, 1700000002.5, "--end"); }),
              HasSubstr("--end 1700000002.5 is a stamp (seconds since 1970), and plan.yaml has no "
                        "stamps"));
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
              HasSubstr("frames (1700000000 s at 30 frames/s), more than urdfsnap's limit"));
}

}  // namespace
}  // namespace urdfsnap::motion
