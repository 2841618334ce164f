// Seeing the robot through a real camera instead of RViz's orbit view: the calibrated camera, where
// it is (a link's frame, a pose, or both), and an optional camera image under the render, as
// RViz's Camera display shows it.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "camera/camera_model.h"
#include "camera/underlay.h"
#include "image/image.h"
#include "scene/orbit_view.h"

namespace urdfsnap::render {

struct CameraSettings {
  // The image's camera: size, intrinsics, distortion, clipping (never null once parsed).
  std::shared_ptr<const camera::CameraModel> model;
  // The link whose frame the camera is attached to, in ROS's optical convention (z forward, x right,
  // y down); "" for the fixed frame.
  std::string frame;
  // The optical frame in `frame` (or in the fixed frame when `frame` is ""), metres.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  // A camera image drawn behind the robot (camera::DrawUnderlay), and its overlay alpha.
  std::shared_ptr<const image::Image> underlay;
  std::string underlay_file;
  double overlay_alpha = camera::kDefaultOverlayAlpha;
};

// RViz's orbit view `view` in a width x height image as the same camera: centred principal point,
// square pixels, its field of view and clipping, the optical frame at the eye in the fixed frame.
// Rendering through it draws what the orbit view draws; keypoints use it when no camera is given.
CameraSettings OrbitCamera(const scene::OrbitView& view, int width, int height);

}  // namespace urdfsnap::render
