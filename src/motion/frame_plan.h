// Which frames an animation has and what each shows: frames at t = k / fps for k = 0 ... floor(T *
// fps), where T is the trajectory's length divided by the playback speed, the trajectory time each
// frame samples, and the camera's yaw for a turntable that turns once around over the animation.
#pragma once

#include <cstdint>
#include <optional>

#include "motion/trajectory.h"

namespace urdfsnap::motion {

// Frame rates above this are refused (no display or format shows them).
inline constexpr double kMaxFramesPerSecond = 1000;
// The most frames one animation may have: ten hours at 300 frames/s; more is taken for a
// mistake (a trajectory in nanoseconds read as seconds).
inline constexpr std::int64_t kMaxFrames = 10'000'000;

struct FramePlan {
  double fps = 30;
  std::int64_t frame_count = 1;
  // trajectory time per frame: speed / fps for times in seconds, speed for a table of rows
  double trajectory_step = 0;
  double trajectory_start = 0;  // the trajectory time of frame 0 (--start)

  // The animation time of `frame`, in seconds.
  double Seconds(std::int64_t frame) const { return frame / fps; }
  // The trajectory time `frame` shows (seconds, or rows for a table without times).
  double TrajectoryTime(std::int64_t frame) const {
    return trajectory_start + frame * trajectory_step;
  }
  // The camera yaw of `frame` for a turntable: `start_yaw` (radians) plus 2 pi * frame /
  // frame_count, one full turn over the animation that loops without a repeated frame.
  double TurntableYaw(std::int64_t frame, double start_yaw) const;
};

// The part of a trajectory to play, in trajectory seconds (see TrajectorySeconds): from `start`
// (default its beginning) to `end` (default its end).
struct TimeWindow {
  std::optional<double> start, end;
};

// The frames of `trajectory` played at `speed` (2 = twice as fast) and `fps` frames per second:
// T = (end - start) / speed (a table without times: T = rows - 1 frames at speed 1), frame k
// showing trajectory time start + k * speed / fps. `duration_seconds`, when given, replaces T;
// past the trajectory's end its last pose holds. Throws Error for an fps, speed or duration that
// is not a positive finite number (fps at most kMaxFramesPerSecond), a window that is empty, starts
// before 0 or after the trajectory's end, or is given for a table without times, or more than
// kMaxFrames frames.
FramePlan PlanFrames(const Trajectory& trajectory, double fps, double speed,
                     std::optional<double> duration_seconds = {}, TimeWindow window = {});

// The trajectory time that `value` of the option `option` (--start, --end) names: seconds from
// the trajectory's start, or, for a trajectory timed by stamps, an absolute stamp (seconds since
// 1970) when `value` is 1e9 or more (2001 onwards: no recording lasts 31 years). Throws Error for
// a stamp given to a trajectory without stamps.
double TrajectorySeconds(const Trajectory& trajectory, double value, const char* option);

// The frames of a still pose shown for `duration_seconds` (a turntable without a trajectory); every
// frame samples trajectory time 0. Throws Error as PlanFrames does.
FramePlan PlanStill(double duration_seconds, double fps);

}  // namespace urdfsnap::motion
