// Closed-form fitting: for a point p at offset q = p − focal, with b the unit vector from the focal
// point to the eye and r, u the camera's right and up vectors, p is in view when
// |q·r| ≤ tan(fov_x/2)·(d − q·b) and |q·u| ≤ tan(fov_y/2)·(d − q·b); the smallest d is the maximum
// of q·b + |q·r|/tan(fov_x/2) and q·b + |q·u|/tan(fov_y/2) over all points.
#include "scene/view_fitting.h"

#include <algorithm>
#include <cmath>

namespace urdfsnap::scene {

namespace {

// Calls `visit` with every vertex of every draw item of `scene`, in the fixed frame.
template <typename Visit>
void ForEachVertex(const Scene& scene, Visit visit) {
  for (const auto& item : scene.items) {
    for (const auto& p : item.mesh->positions) visit(item.X_FG * p.cast<double>());
  }
}

}  // namespace

OrbitView FitView(int count, const std::function<Scene(int)>& scene_of, OrbitView view, double aspect,
                  bool keep_focal, double margin) {
  Eigen::AlignedBox3d box;
  for (int k = 0; k < count; ++k) ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) { box.extend(p); });
  if (box.isEmpty()) return view;
  if (!keep_focal) view.focal = box.center();
  const Eigen::Matrix4d V = ViewMatrix(view);
  const Eigen::Vector3d right = V.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = V.block<1, 3>(1, 0).transpose();
  const Eigen::Vector3d back = V.block<1, 3>(2, 0).transpose();
  const double tan_y = std::tan(view.fov_y / 2) * (1 - 2 * margin);
  const double tan_x = std::tan(view.fov_y / 2) * aspect * (1 - 2 * margin);
  double distance = 0;
  for (int k = 0; k < count; ++k) {
    ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) {
      const Eigen::Vector3d q = p - view.focal;
      const double depth_offset = q.dot(back);
      // in the image, and in front of the near clip plane
      distance = std::max({distance, depth_offset + std::abs(q.dot(right)) / tan_x,
                           depth_offset + std::abs(q.dot(up)) / tan_y, depth_offset + view.near_clip});
    });
  }
  view.distance = std::max(distance, view.near_clip * 2);
  return view;
}

OrbitView FitView(const Scene& scene, OrbitView view, double aspect, bool keep_focal, double margin) {
  return FitView(1, [&](int) { return scene; }, view, aspect, keep_focal, margin);
}

}  // namespace urdfsnap::scene
