// Closed-form fitting: for a point p at offset q = p − focal, with b the unit vector from the focal
// point to the eye and r, u the camera's right and up vectors, p is in view when
// |q·r| ≤ tan(fov_x/2)·(d − q·b) and |q·u| ≤ tan(fov_y/2)·(d − q·b); the smallest d is the maximum
// of q·b + |q·r|/tan(fov_x/2) and q·b + |q·u|/tan(fov_y/2) over all points.
#include "scene/view_fitting.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace urdfsnap::scene {

namespace {

// Visits the vertices of scenes in turn, skipping a scene placed exactly as the one before it
// (the same meshes at the same poses, as every frame of a still turntable is): its vertices can
// neither widen a bound nor raise a maximum.
class DistinctScenes {
 public:
  // Calls `visit` with every vertex of every draw item of `scene`, in the fixed frame, unless the
  // scene before it was placed the same.
  template <typename Visit>
  void ForEachVertex(const Scene& scene, Visit visit) {
    if (SameAsLast(scene)) return;
    for (const auto& item : scene.items) {
      for (const auto& p : item.mesh->positions) visit(item.X_FG * p.cast<double>());
    }
  }

 private:
  bool SameAsLast(const Scene& scene) {
    const bool same = has_last_ && scene.items.size() == last_.size() &&
                      std::equal(scene.items.begin(), scene.items.end(), last_.begin(),
                                 [](const DrawItem& item, const Placement& placed) {
                                   return item.mesh.get() == placed.mesh && item.X_FG.matrix() == placed.X_FG.matrix();
                                 });
    if (same) return true;
    has_last_ = true;
    last_.clear();
    for (const auto& item : scene.items) last_.push_back({item.mesh.get(), item.X_FG});
    return false;
  }

  struct Placement {
    const geometry::TriangleMesh* mesh;
    Eigen::Affine3d X_FG;
  };
  bool has_last_ = false;
  std::vector<Placement> last_;
};

}  // namespace

OrbitView FitView(int count, const std::function<Scene(int)>& scene_of, OrbitView view, double aspect,
                  bool keep_focal, double margin) {
  // the box gives the focal point; with the focal point kept it is not needed
  if (!keep_focal) {
    Eigen::AlignedBox3d box;
    DistinctScenes scenes;
    for (int k = 0; k < count; ++k) scenes.ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) { box.extend(p); });
    if (box.isEmpty()) return view;
    view.focal = box.center();
  }
  const Eigen::Matrix4d V = ViewMatrix(view);
  const Eigen::Vector3d right = V.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = V.block<1, 3>(1, 0).transpose();
  const Eigen::Vector3d back = V.block<1, 3>(2, 0).transpose();
  const double tan_y = std::tan(view.fov_y / 2) * (1 - 2 * margin);
  const double tan_x = std::tan(view.fov_y / 2) * aspect * (1 - 2 * margin);
  double distance = 0;
  bool any = false;
  DistinctScenes scenes;
  for (int k = 0; k < count; ++k) {
    scenes.ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) {
      const Eigen::Vector3d q = p - view.focal;
      const double depth_offset = q.dot(back);
      // in the image, and in front of the near clip plane
      distance = std::max({distance, depth_offset + std::abs(q.dot(right)) / tan_x,
                           depth_offset + std::abs(q.dot(up)) / tan_y, depth_offset + view.near_clip});
      any = true;
    });
  }
  if (!any) return view;
  view.distance = std::max(distance, view.near_clip * 2);
  return view;
}

OrbitView FitView(const Scene& scene, OrbitView view, double aspect, bool keep_focal, double margin) {
  return FitView(1, [&](int) { return scene; }, view, aspect, keep_focal, margin);
}

}  // namespace urdfsnap::scene
