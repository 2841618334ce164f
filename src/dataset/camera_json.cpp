// CameraJson: intrinsics, distortion and pose as plain JSON numbers.
#include "dataset/camera_json.h"

#include <vector>

namespace urdfsnap::dataset {

nlohmann::ordered_json CameraJson(const camera::CameraModel& camera, const Eigen::Isometry3d& X_FC) {
  const camera::Intrinsics& k = camera.intrinsics();
  const bool rational = camera.distortion_model() == "rational_polynomial";
  const auto& d = camera.distortion().k;
  Eigen::Quaterniond q(X_FC.rotation());
  if (q.w() < 0) q.coeffs() = -q.coeffs();   // the same rotation; w ≥ 0 as tf2 prints it mostly
  const Eigen::Vector3d t = X_FC.translation();
  nlohmann::ordered_json json;
  json["width"] = camera.width();
  json["height"] = camera.height();
  json["K"] = {k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0};
  json["D"] = std::vector<double>(d.begin(), d.begin() + (rational ? 8 : 5));
  json["distortion_model"] = rational ? "rational_polynomial" : "plumb_bob";
  json["pose"] = {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
  return json;
}

}  // namespace urdfsnap::dataset
