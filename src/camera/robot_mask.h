// The robot's binary mask from its link-label image, optionally grown by N pixels, as a robot
// self-filter wants it (pixels near the robot's outline are dropped from a depth image too).
#pragma once

#include "image/image.h"

namespace urdfsnap::camera {

// 255 where the robot is (label ≠ 0) or within `dilate` pixels of it (Euclidean distance between
// pixel centres), 0 elsewhere. `dilate` ≥ 0; 0 is the robot's pixels exactly.
image::Gray8Image RobotMask(const image::LabelImage& labels, int dilate);

}  // namespace urdfsnap::camera
