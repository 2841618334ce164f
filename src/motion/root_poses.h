// Where the robot stands in a fixed frame outside it (RViz's Fixed Frame set to odom or map): at
// each moment of a bag, the pose its TF gives the robot's root link in that frame, so that a mobile
// robot drives across the grid as RViz shows it.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "tf/tf_buffer.h"

namespace urdfsnap::motion {

class RootPoses {
 public:
  // `buffer`: the bag's transforms (tf::ReadBagTransforms of `bag`); `root`: the robot's root link;
  // `stamp_at_zero`: the stamp (seconds since 1970) of trajectory time 0. Throws urdfsnap::Error
  // "--fixed-frame 'map': ..." (`option` naming the frame) when TF does not connect the fixed
  // frame to the root. A camera's TF frame (animate's --camera-frame) is followed the same way.
  RootPoses(std::shared_ptr<const tf::TfBuffer> buffer, std::string fixed_frame, std::string root, double stamp_at_zero,
            const std::string& bag, const std::string& option = "--fixed-frame");

  // X_FR, the root's pose in the fixed frame at trajectory time `t` (seconds). Outside the
  // recorded transforms the nearest one holds, with one warning (the same for every frame).
  Eigen::Isometry3d At(double t, Warnings& warnings) const;

  const std::string& root() const { return root_; }
  const std::string& fixed_frame() const { return fixed_frame_; }

 private:
  std::shared_ptr<const tf::TfBuffer> buffer_;
  std::string fixed_frame_, root_, bag_;
  double stamp_at_zero_;
};

}  // namespace urdfsnap::motion
