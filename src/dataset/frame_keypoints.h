// Where the robot's link frames and joint origins land in a camera image: their pixels under the
// camera model (distortion included, as OpenCV's projectPoints gives them), their depth along the
// optical axis, whether they are inside the image and whether robot geometry hides them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "camera/camera_model.h"
#include "image/image.h"
#include "model/robot.h"

namespace urdfsnap::dataset {

// How far in front of a point a surface of another link may be before it hides the point, in
// metres: depth values are exact samples of the drawn triangles, so 1 cm only absorbs their
// rasterisation; a point inside its own link's body stays visible through that body.
inline constexpr double kOcclusionTolerance = 0.01;

struct FrameKeypoint {
  enum class Kind { kLink, kJoint };
  std::string name;
  Kind kind = Kind::kLink;
  std::optional<Eigen::Vector2d> uv;   // pixel, OpenCV's convention; nullopt behind the camera
  double depth = 0;                    // m along the optical axis (negative behind the camera)
  bool in_image = false;               // in front of the camera and within the image's pixels
  bool visible = false;                // in_image, and no other link's surface in front of it
};

// The keypoints of every link frame (links() order) and then every joint origin (joints() order)
// for link poses X_RL (model::ComputeLinkPoses), seen by `camera` with its optical frame at X_RC
// in the root frame. A point is visible when it is in the image and, at its nearest pixel, the
// label image shows no robot, one of its own links (the link; a joint's parent or child), or a
// surface less than kOcclusionTolerance in front of it in the depth image. `depth` and `labels`
// are the camera's images of the same pose.
std::vector<FrameKeypoint> ProjectKeypoints(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_RL,
                                            const Eigen::Isometry3d& X_RC, const camera::CameraModel& camera,
                                            const image::DepthImage& depth, const image::LabelImage& labels);

}  // namespace urdfsnap::dataset
