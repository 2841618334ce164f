// RootPoses: one TfBuffer lookup per frame, fixed frame to root link.
#include "motion/root_poses.h"

#include <cmath>

#include "common/error.h"

namespace urdfsnap::motion {

RootPoses::RootPoses(std::shared_ptr<const tf::TfBuffer> buffer, std::string fixed_frame, std::string root,
                     double stamp_at_zero, const std::string& bag, const std::string& option)
    : buffer_(std::move(buffer)), fixed_frame_(std::move(fixed_frame)), root_(std::move(root)),
      bag_(bag), stamp_at_zero_(stamp_at_zero) {
  if (buffer_->Find(fixed_frame_, root_, 0)) return;
  std::string frames;
  for (const std::string& frame : buffer_->frames()) frames += (frames.empty() ? "'" : ", '") + frame + "'";
  throw Error(option + " '" + fixed_frame_ + "': neither a link of the robot nor a frame that " + bag_ +
              "'s /tf and /tf_static connect to its root link '" + root_ + "' (" +
              (frames.empty() ? std::string("the bag has no TF") : "its TF frames: " + frames) + ")");
}

Eigen::Isometry3d RootPoses::At(double t, Warnings& warnings) const {
  const auto time_ns = static_cast<std::int64_t>(std::llround((stamp_at_zero_ + t) * 1e9));
  const tf::Lookup lookup = *buffer_->Find(fixed_frame_, root_, time_ns);
  if (lookup.extrapolated) {
    warnings.Add(bag_ + ": TF from '" + fixed_frame_ + "' to '" + root_ +
                 "' is not recorded at some frames' times (before its first or after its last "
                 "transform); those frames hold the nearest one");
  }
  return lookup.X_TS;
}

}  // namespace urdfsnap::motion
