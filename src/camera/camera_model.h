// The camera an image is seen through, as a calibrated camera sees it: the image size, the
// intrinsics, the lens distortion when the raw image is wanted, and the clipping distances; with
// what the GL renderer needs to draw it (a pinhole image and its projection matrix) and what turns
// that drawing into the camera's image.
#pragma once

#include <memory>
#include <optional>

#include <Eigen/Geometry>

#include "camera/camera_info.h"
#include "camera/distortion_remap.h"
#include "image/image.h"

namespace urdfsnap::camera {

// Near and far clipping distances along the optical axis, in metres; RViz's Camera display's
// (camera_display.cpp updateCamera: near_plane 0.01, far_plane 100).
struct Clipping {
  double near = 0.01;
  double far = 100;
};

class CameraModel {
 public:
  // `info`'s camera: the rectified image (P's intrinsics, as RViz's Camera display draws), or with
  // `distort` the raw image (K and D, as the camera delivers it). P's Tx and Ty (a stereo pair's
  // right camera) move the camera along its x and y axes as RViz moves it.
  CameraModel(const CameraInfo& info, bool distort, Clipping clipping);

  // A distortion-free camera with square pixels, vertical field of view `fov_y` (rad) and the
  // principal point at the image centre.
  CameraModel(double fov_y, int width, int height, Clipping clipping);

  int width() const { return image_.width; }
  int height() const { return image_.height; }
  // The intrinsics and distortion of the images made (the distortion is zero unless distorted).
  const Intrinsics& intrinsics() const { return image_.k; }
  const Distortion& distortion() const { return distortion_; }
  // The name of the distortion model applied: "plumb_bob", "rational_polynomial" or "" for none.
  const std::string& distortion_model() const { return distortion_model_; }
  const Clipping& clipping() const { return clipping_; }

  // Where the camera's optical frame is, given the pose X_WF of the frame it is attached to.
  Eigen::Isometry3d Pose(const Eigen::Isometry3d& X_WF) const;

  // The pixel (u, v) of point p_C in the optical frame (metres; z forward, x right, y down),
  // distortion included, as OpenCV's projectPoints gives it; nullopt for points not in front of
  // the camera (z ≤ 0).
  std::optional<Eigen::Vector2d> Project(const Eigen::Vector3d& p_C) const;

  // The pinhole image the renderer draws: this camera's own without distortion, otherwise one
  // covering the rays of every raw pixel.
  const PinholeImage& drawn() const;
  // drawn()'s OpenGL projection with this camera's clipping (see GlProjection).
  Eigen::Matrix4d GlProjection() const;

  // This camera's frame from the frame rendered through drawn(): itself, or remapped through the
  // lens.
  image::Frame Finish(image::Frame drawn) const;

 private:
  PinholeImage image_;
  Distortion distortion_;
  std::string distortion_model_;
  Eigen::Vector3d offset_C_ = Eigen::Vector3d::Zero();   // P's Tx, Ty
  Clipping clipping_;
  std::shared_ptr<const DistortionRemap> remap_;         // null without distortion
};

// OpenGL's view matrix (camera looking down −Z, +Y up) of an optical frame at X_WC.
Eigen::Matrix4d GlViewMatrix(const Eigen::Isometry3d& X_WC);

}  // namespace urdfsnap::camera
