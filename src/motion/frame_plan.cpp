// PlanFrames and PlanStill: argument checks and the frame count, with a small tolerance so that
// T * fps landing a rounding error below a whole number still counts that frame. Times the user
// typed and stamps are echoed exactly (FormatNumber); counts and durations rounded for people.
#include "motion/frame_plan.h"

#include <cmath>
#include <numbers>
#include <string>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::motion {
namespace {

void CheckPositive(double value, const char* what, double most = HUGE_VAL) {
  if (!std::isfinite(value) || value <= 0 || value > most) {
    throw Error(std::string(what) + " must be a positive number" +
                (most < HUGE_VAL ? " up to " + FormatNumber(most) : std::string()) + ", got " +
                FormatNumber(value));
  }
}

FramePlan Plan(double seconds, double fps, double trajectory_step) {
  FramePlan plan;
  plan.fps = fps;
  plan.trajectory_step = trajectory_step;
  const double last_frame = std::floor(seconds * fps + 1e-9);
  if (!(last_frame < kMaxFrames)) {
    throw Error("the animation would have " + FormatForPeople(last_frame + 1) + " frames (" +
                FormatForPeople(seconds, "s") + " at " + FormatForPeople(fps) +
                " frames/s), more than urdfsnap's limit of " + std::to_string(kMaxFrames));
  }
  plan.frame_count = static_cast<std::int64_t>(last_frame) + 1;
  return plan;
}

}  // namespace

double FramePlan::TurntableYaw(std::int64_t frame, double start_yaw) const {
  return start_yaw + 2 * std::numbers::pi * static_cast<double>(frame) / frame_count;
}

FramePlan PlanFrames(const Trajectory& trajectory, double fps, double speed,
                     std::optional<double> duration_seconds, TimeWindow window) {
  CheckPositive(fps, "the frame rate (frames per second)", kMaxFramesPerSecond);
  CheckPositive(speed, "the playback speed");
  if (duration_seconds) CheckPositive(*duration_seconds, "the duration (seconds)");
  const bool rows = trajectory.time_base == TimeBase::kRows;
  if (rows && (window.start || window.end)) {
    throw Error("--start and --end are times; " + trajectory.source +
                " is a table without a time column (one row per frame)");
  }
  const double end = window.end.value_or(trajectory.EndTime());
  const double start = window.start.value_or(0);
  if (start < 0 || start > trajectory.EndTime()) {
    throw Error("--start " + FormatNumber(start) + " s is outside " + trajectory.source + ", which lasts " +
                FormatNumber(trajectory.EndTime()) + " s (--start from 0 to " + FormatNumber(trajectory.EndTime()) +
                ")");
  }
  if (window.end && end <= start) {
    throw Error("--end " + FormatNumber(end) + " s is not after the start at " + FormatNumber(start) + " s");
  }
  // a table without times shows row k at frame k (at speed 1)
  const double end_seconds = rows ? trajectory.EndTime() / fps : end - start;
  FramePlan plan = Plan(duration_seconds.value_or(end_seconds / speed), fps, rows ? speed : speed / fps);
  plan.trajectory_start = start;
  return plan;
}

double TrajectorySeconds(const Trajectory& trajectory, double value, const char* option) {
  constexpr double kFirstStamp = 1e9;
  if (value < kFirstStamp) return value;
  if (!trajectory.stamp_at_zero) {
    throw Error(std::string(option) + " " + FormatNumber(value) + " is a stamp (seconds since 1970), and " +
                trajectory.source + " has no stamps; give seconds from its start");
  }
  return value - *trajectory.stamp_at_zero;
}

FramePlan PlanStill(double duration_seconds, double fps) {
  CheckPositive(fps, "the frame rate (frames per second)", kMaxFramesPerSecond);
  CheckPositive(duration_seconds, "the duration (seconds)");
  return Plan(duration_seconds, fps, 0);
}

}  // namespace urdfsnap::motion
