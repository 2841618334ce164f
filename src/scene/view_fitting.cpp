// Closed-form fitting: for a point p at offset q = p − focal, with b the unit vector from the focal
// point to the eye and r, u the camera's right and up vectors, p is in view when
// |q·r| ≤ tan(fov_x/2)·(d − q·b) and |q·u| ≤ tan(fov_y/2)·(d − q·b); the smallest d is the maximum
// of q·b + |q·r|/tan(fov_x/2) and q·b + |q·u|/tan(fov_y/2) over all points.
#include "scene/view_fitting.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

// The least distance from `view`'s focal point, along its own yaw, pitch and field of view, at
// which one vertex lies in the image shrunk by `margin` and in front of the near clip plane.
class Framing {
 public:
  Framing(const OrbitView& view, double aspect, double margin)
      : focal_(view.focal),
        near_clip_(view.near_clip),
        tan_x_(std::tan(view.fov_y / 2) * aspect * (1 - 2 * margin)),
        tan_y_(std::tan(view.fov_y / 2) * (1 - 2 * margin)) {
    const Eigen::Matrix4d V = ViewMatrix(view);
    right_ = V.block<1, 3>(0, 0).transpose();
    up_ = V.block<1, 3>(1, 0).transpose();
    back_ = V.block<1, 3>(2, 0).transpose();
  }

  double Distance(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = p - focal_;
    const double depth_offset = q.dot(back_);
    // in the image, and in front of the near clip plane
    return std::max({depth_offset + std::abs(q.dot(right_)) / tan_x_, depth_offset + std::abs(q.dot(up_)) / tan_y_,
                     depth_offset + near_clip_});
  }

 private:
  Eigen::Vector3d focal_, right_, up_, back_;
  double near_clip_, tan_x_, tan_y_;
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
  const Framing framing(view, aspect, margin);
  double distance = 0;
  bool any = false;
  DistinctScenes scenes;
  for (int k = 0; k < count; ++k) {
    scenes.ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) {
      distance = std::max(distance, framing.Distance(p));
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

double FitDistance(const Scene& scene, const OrbitView& view, const std::vector<double>& yaws, double aspect,
                   double margin) {
  // each vertex placed once (the same point of a mesh once per placement), not once per yaw
  std::vector<Eigen::Vector3d> points;
  for (const auto& item : scene.items) {
    // equal bit for bit: a total order even with NaNs in a hostile mesh
    std::vector<Eigen::Vector3f> local = item.mesh->positions;
    std::sort(local.begin(), local.end(), [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
      return std::memcmp(a.data(), b.data(), sizeof(float) * 3) < 0;
    });
    local.erase(std::unique(local.begin(), local.end(),
                            [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
                              return std::memcmp(a.data(), b.data(), sizeof(float) * 3) == 0;
                            }),
                local.end());
    for (const auto& p : local) points.push_back(item.X_FG * p.cast<double>());
  }
  if (points.empty()) return 0;
  double fitted = 0;
  for (const double yaw : yaws) {
    OrbitView side = view;
    side.yaw = yaw;
    const Framing framing(side, aspect, margin);
    double distance = 0;
    for (const auto& p : points) distance = std::max(distance, framing.Distance(p));
    fitted = std::max({fitted, distance, view.near_clip * 2});
  }
  return fitted;
}

}  // namespace urdfsnap::scene
