// The points a turntable's fit keeps of a 3-D set: the hull's corners and the points on or near
// its faces, not those well inside; every point when the set spans no volume or is not finite (unit).
#include "scene/hull_candidates.h"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace urdfsnap::scene {
namespace {

// The eight corners of the cube [-1, 1]^3.
std::vector<Eigen::Vector3d> CubeCorners() {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  return corners;
}

TEST(HullCandidates, KeepsCornersAndFacesDropsTheInside) {
  std::vector<Eigen::Vector3d> points = CubeCorners();
  const size_t corners = points.size();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> inside(-0.99, 0.99);
  for (int i = 0; i < 500; ++i) points.emplace_back(inside(random), inside(random), inside(random));
  const size_t on_faces = points.size();
  // on a face, on an edge, a repeated corner, and a hair (1e-12) inside a face
  points.insert(points.end(), {{1, 0.3, -0.2}, {0.5, 1, 1}, {-1, -1, -1}, {0.2, 0.1, 1 - 1e-12}});
  const std::vector<bool> kept = HullCandidates(points);
  ASSERT_EQ(kept.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    if (i < corners || i >= on_faces) {
      EXPECT_TRUE(kept[i]) << "point " << i << " (" << points[i].transpose() << ") is on the hull";
    } else {
      EXPECT_FALSE(kept[i]) << "point " << i << " (" << points[i].transpose() << ") is well inside";
    }
  }
}

TEST(HullCandidates, KeepsEveryPointWithoutAVolumeOrWithANonFiniteCoordinate) {
  const auto all_kept = [](const std::vector<Eigen::Vector3d>& points) {
    const std::vector<bool> kept = HullCandidates(points);
    return kept.size() == points.size() && std::find(kept.begin(), kept.end(), false) == kept.end();
  };
  EXPECT_TRUE(HullCandidates({}).empty());
  std::vector<Eigen::Vector3d> flat;   // a square's grid: corners, edges and inside all in z = 0
  for (int i = 0; i < 25; ++i) flat.emplace_back(i % 5, i / 5, 0);
  EXPECT_TRUE(all_kept(flat));
  EXPECT_TRUE(all_kept({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  std::vector<Eigen::Vector3d> points = CubeCorners();
  points.emplace_back(0, 0, 0);
  EXPECT_FALSE(HullCandidates(points).back());
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    std::vector<Eigen::Vector3d> with_bad = points;
    with_bad.emplace_back(bad, 0, 0);
    EXPECT_TRUE(all_kept(with_bad));
  }
}

}  // namespace
}  // namespace urdfsnap::scene
