// PlanFrames and PlanStill: argument checks and the frame count, with a small tolerance so that
// T * fps landing a rounding error below a whole number still counts that frame.
#include "motion/frame_plan.h"

#include <cmath>
#include <numbers>

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
    throw Error("the animation would have " + FormatNumber(last_frame + 1) + " frames (" +
                FormatNumber(seconds) + " s at " + FormatNumber(fps) +
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
                     std::optional<double> duration_seconds) {
  CheckPositive(fps, "the frame rate (frames per second)", kMaxFramesPerSecond);
  CheckPositive(speed, "the playback speed");
  if (duration_seconds) CheckPositive(*duration_seconds, "the duration (seconds)");
  const bool rows = trajectory.time_base == TimeBase::kRows;
  // a table without times shows row k at frame k (at speed 1)
  const double end_seconds = rows ? trajectory.EndTime() / fps : trajectory.EndTime();
  return Plan(duration_seconds.value_or(end_seconds / speed), fps, rows ? speed : speed / fps);
}

FramePlan PlanStill(double duration_seconds, double fps) {
  CheckPositive(fps, "the frame rate (frames per second)", kMaxFramesPerSecond);
  CheckPositive(duration_seconds, "the duration (seconds)");
  return Plan(duration_seconds, fps, 0);
}

}  // namespace urdfsnap::motion
