// Andrew's monotone chain over the points the Akl–Toussaint octagon test leaves.
#include "scene/convex_hull_2d.h"

#include <algorithm>
#include <array>

namespace urdfsnap::scene {

namespace {

// > 0 when o → a → b turns counter-clockwise.
double Turn(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Drops the points strictly inside the polygon of the extremes in eight directions (counter-
// clockwise order of the directions keeps the polygon convex and counter-clockwise).
void DropInsideOctagon(std::vector<Eigen::Vector2d>& points) {
  static const std::array<Eigen::Vector2d, 8> directions = {
      Eigen::Vector2d(1, 0),  Eigen::Vector2d(1, 1),   Eigen::Vector2d(0, 1),  Eigen::Vector2d(-1, 1),
      Eigen::Vector2d(-1, 0), Eigen::Vector2d(-1, -1), Eigen::Vector2d(0, -1), Eigen::Vector2d(1, -1)};
  std::array<Eigen::Vector2d, 8> extreme;
  extreme.fill(points.front());
  for (const auto& p : points) {
    for (size_t i = 0; i < directions.size(); ++i) {
      if (p.dot(directions[i]) > extreme[i].dot(directions[i])) extreme[i] = p;
    }
  }
  // one distinct extreme: every point is that point, and no polygon encloses anything
  if (std::all_of(extreme.begin(), extreme.end(), [&](const Eigen::Vector2d& e) { return e == extreme[0]; })) return;
  const auto inside = [&](const Eigen::Vector2d& p) {
    for (size_t i = 0; i < extreme.size(); ++i) {
      const Eigen::Vector2d& a = extreme[i];
      const Eigen::Vector2d& b = extreme[(i + 1) % extreme.size()];
      if (a != b && Turn(a, b, p) <= 0) return false;
    }
    return true;
  };
  std::erase_if(points, inside);
}

}  // namespace

std::vector<Eigen::Vector2d> ConvexHull2d(std::vector<Eigen::Vector2d> points) {
  if (points.empty()) return points;
  DropInsideOctagon(points);
  std::sort(points.begin(), points.end(),
            [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  size_t k = 0;
  // lower chain left to right, then upper chain right to left
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && Turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && Turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace urdfsnap::scene
