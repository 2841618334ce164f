// Exact fitting from the convex hulls of the vertices seen along each image axis. With r, u and b
// the camera's right, up and back (towards the eye) unit vectors and t = tan of half the field of
// view on an axis a (r or u), a point p is inside the frame on that axis when
// p·(±a + t·b) ≤ E·(±a + t·b) for the eye E. Writing h±(t) = max over p of p·(±a + t·b), the eye
// whose frame touches the silhouette on both sides of the axis has E·a = (h+ − h−)/2 and
// E·b = (h+ + h−)/(2t): centred on that axis, as near as that half-angle allows. The eye's depth
// E·b is the larger of the two axes' (the axis that binds); on the other axis the half-angle t' < t
// that touches both sides from that depth is found by bisection (the touching depth falls as t'
// grows) and centres it. Only hull corners can reach a maximum, so the vertices are reduced to
// two small 2D hulls, (p·r, p·b) and (p·u, p·b), as the scenes arrive. A turntable's one scene
// seen from many yaws is first reduced, once, to the points near its 3-D hull (HullCandidates).
#include "scene/view_fitting.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "scene/convex_hull_2d.h"
#include "scene/hull_candidates.h"

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

// One image axis: the hull of (p·a, p·b) over every vertex, and the half-angle's tangent there.
struct AxisHull {
  std::vector<Eigen::Vector2d> corners;
  double tan_half = 0;

  // max over the corners of side·(p·a) + t·(p·b)
  double Support(double side, double t) const {
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& c : corners) best = std::max(best, side * c.x() + t * c.y());
    return best;
  }
  // the eye's depth E·b whose frame of half-angle tangent t touches both sides
  double TouchingDepth(double t) const { return (Support(1, t) + Support(-1, t)) / (2 * t); }
  // the eye's E·a that centres the silhouette with half-angle tangent t
  double CentredOffset(double t) const { return (Support(1, t) - Support(-1, t)) / 2; }

  // E·a of the eye at depth `depth` (≥ TouchingDepth(tan_half)) that centres this axis.
  double OffsetFrom(double depth) const {
    double low = tan_half * 1e-9, high = tan_half;
    if (TouchingDepth(high) >= depth || TouchingDepth(low) <= depth) {
      return CentredOffset(TouchingDepth(high) >= depth ? high : low);
    }
    for (int i = 0; i < 60; ++i) {
      const double mid = (low + high) / 2;
      (TouchingDepth(mid) > depth ? low : high) = mid;
    }
    return CentredOffset((low + high) / 2);
  }

  // the least distance from `focal` along b at which every corner is inside ±tan_half about it
  double DistanceAround(double focal_a, double focal_b) const {
    double distance = 0;
    for (const auto& c : corners) {
      distance = std::max(distance, c.y() - focal_b + std::abs(c.x() - focal_a) / tan_half);
    }
    return distance;
  }
};

// The camera's right, up and back directions (rows of the view matrix) and the two image axes'
// empty hulls, their half-angle tangents narrowed by the margin.
struct FitStart {
  Eigen::Vector3d right, up, back;
  AxisHull across, upward;
};

FitStart StartFit(const OrbitView& view, double aspect, FitMargin margin) {
  const Eigen::Matrix4d V = ViewMatrix(view);
  FitStart start{V.block<1, 3>(0, 0).transpose(), V.block<1, 3>(1, 0).transpose(), V.block<1, 3>(2, 0).transpose(), {}, {}};
  start.across.tan_half = std::tan(view.fov_y / 2) * aspect * (1 - 2 * margin.x);
  start.upward.tan_half = std::tan(view.fov_y / 2) * (1 - 2 * margin.y);
  return start;
}

// Adds the vertices of every distinct scene to the two axis hulls, re-hulling after each scene.
bool Collect(int count, const std::function<Scene(int)>& scene_of, const Eigen::Vector3d& right,
             const Eigen::Vector3d& up, const Eigen::Vector3d& back, AxisHull& across, AxisHull& upward) {
  DistinctScenes scenes;
  for (int k = 0; k < count; ++k) {
    std::vector<Eigen::Vector2d> x = across.corners, y = upward.corners;
    scenes.ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) {
      const double depth = p.dot(back);
      x.emplace_back(p.dot(right), depth);
      y.emplace_back(p.dot(up), depth);
    });
    if (x.size() == across.corners.size()) continue;
    across.corners = ConvexHull2d(std::move(x));
    upward.corners = ConvexHull2d(std::move(y));
  }
  return !across.corners.empty();
}

// The least distance from `view`'s focal point, along its own yaw, pitch and field of view, at
// which every corner is inside the image shrunk by the margin (the axes' tan_half) and in front
// of the near clip plane. `back` is the camera's back axis, across.corners' second coordinate.
double KeptFocalDistance(const AxisHull& across, const AxisHull& upward, const OrbitView& view,
                         const Eigen::Vector3d& right, const Eigen::Vector3d& up, const Eigen::Vector3d& back) {
  double nearest = -std::numeric_limits<double>::infinity();
  for (const auto& c : across.corners) nearest = std::max(nearest, c.y());
  const double distance = std::max({across.DistanceAround(view.focal.dot(right), view.focal.dot(back)),
                                    upward.DistanceAround(view.focal.dot(up), view.focal.dot(back)),
                                    nearest - view.focal.dot(back) + view.near_clip});
  return std::max(distance, view.near_clip * 2);
}

// The bytes of a mesh point as memcmp orders them (each float's first byte in memory, its least
// significant, first): equal for equal bytes, a total order even with NaNs in a hostile mesh.
std::array<std::uint32_t, 3> ByteOrder(const Eigen::Vector3f& p) {
  return {__builtin_bswap32(std::bit_cast<std::uint32_t>(p.x())), __builtin_bswap32(std::bit_cast<std::uint32_t>(p.y())),
          __builtin_bswap32(std::bit_cast<std::uint32_t>(p.z()))};
}

// Every vertex of every draw item in the fixed frame, a point of a mesh once per placement (equal
// bit for bit), not once per triangle using it.
std::vector<Eigen::Vector3d> PlacedOnce(const Scene& scene) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& item : scene.items) {
    std::vector<Eigen::Vector3f> local = item.mesh->positions;
    std::sort(local.begin(), local.end(),
              [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return ByteOrder(a) < ByteOrder(b); });
    local.erase(std::unique(local.begin(), local.end(),
                            [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return ByteOrder(a) == ByteOrder(b); }),
                local.end());
    for (const auto& p : local) points.push_back(item.X_FG * p.cast<double>());
  }
  return points;
}

}  // namespace

OrbitView FitView(int count, const std::function<Scene(int)>& scene_of, OrbitView view, double aspect,
                  bool keep_focal, FitMargin margin) {
  auto [right, up, back, across, upward] = StartFit(view, aspect, margin);
  if (!Collect(count, scene_of, right, up, back, across, upward)) return view;
  double nearest = -std::numeric_limits<double>::infinity(), farthest = -nearest;
  for (const auto& c : across.corners) {
    nearest = std::max(nearest, c.y());
    farthest = std::min(farthest, c.y());
  }
  if (keep_focal) {
    view.distance = KeptFocalDistance(across, upward, view, right, up, back);
    return view;
  }
  // the eye in the camera's axes: as far back as the binding axis needs, in front of the near plane
  const double depth = std::max({across.TouchingDepth(across.tan_half), upward.TouchingDepth(upward.tan_half),
                                 nearest + view.near_clip});
  const Eigen::Vector3d eye = across.OffsetFrom(depth) * right + upward.OffsetFrom(depth) * up + depth * back;
  view.distance = std::max(depth - (nearest + farthest) / 2, view.near_clip * 2);
  view.focal = eye - view.distance * back;
  return view;
}

OrbitView FitView(const Scene& scene, OrbitView view, double aspect, bool keep_focal, FitMargin margin) {
  return FitView(1, [&](int) { return scene; }, view, aspect, keep_focal, margin);
}

std::optional<Eigen::Vector3d> BoundsCentre(int count, const std::function<Scene(int)>& scene_of) {
  Eigen::AlignedBox3d box;
  DistinctScenes scenes;
  for (int k = 0; k < count; ++k) scenes.ForEachVertex(scene_of(k), [&](const Eigen::Vector3d& p) { box.extend(p); });
  if (box.isEmpty()) return std::nullopt;
  return box.center();
}

double FitDistance(const Scene& scene, const OrbitView& view, const std::vector<double>& yaws, double aspect,
                   FitMargin margin) {
  std::vector<Eigen::Vector3d> points = PlacedOnce(scene);
  if (points.empty()) return 0;
  // only the points that can be corners of some yaw's hulls, found once
  const std::vector<bool> candidate = HullCandidates(points);
  std::vector<Eigen::Vector3d> corners;
  for (size_t i = 0; i < points.size(); ++i) {
    if (candidate[i]) corners.push_back(points[i]);
  }
  double fitted = 0;
  std::vector<Eigen::Vector2d> x, y;
  for (const double yaw : yaws) {
    // FitView's keep_focal arithmetic on the same hulls, so the result is the same bit for bit
    OrbitView side = view;
    side.yaw = yaw;
    auto [right, up, back, across, upward] = StartFit(side, aspect, margin);
    x.clear();
    y.clear();
    for (const auto& p : corners) {
      const double depth = p.dot(back);
      x.emplace_back(p.dot(right), depth);
      y.emplace_back(p.dot(up), depth);
    }
    across.corners = ConvexHull2d(x);
    upward.corners = ConvexHull2d(y);
    fitted = std::max(fitted, KeptFocalDistance(across, upward, side, right, up, back));
  }
  return fitted;
}

}  // namespace urdfsnap::scene
