// The convex hull --fit reduces a robot's vertices to: corners only, counter-clockwise, every
// point inside, degenerate sets kept (unit).
#include "scene/convex_hull_2d.h"

#include <random>

#include <gtest/gtest.h>

namespace urdfsnap::scene {
namespace {

double Turn(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

TEST(ConvexHull2d, ASquareWithPointsInsideAndOnItsEdgesIsItsFourCorners) {
  std::vector<Eigen::Vector2d> points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 0}, {2, 1}, {0.5, 1.5}, {0, 0}};
  const std::vector<Eigen::Vector2d> hull = ConvexHull2d(points);
  ASSERT_EQ(hull.size(), 4u);
  for (size_t i = 0; i < hull.size(); ++i) {
    EXPECT_GT(Turn(hull[i], hull[(i + 1) % 4], hull[(i + 2) % 4]), 0) << "counter-clockwise corners";
  }
  EXPECT_EQ(hull[0], Eigen::Vector2d(0, 0));
}

TEST(ConvexHull2d, DegenerateSets) {
  EXPECT_TRUE(ConvexHull2d({}).empty());
  EXPECT_EQ(ConvexHull2d({{1, 2}, {1, 2}, {1, 2}}), std::vector<Eigen::Vector2d>({{1, 2}}));
  const std::vector<Eigen::Vector2d> line = ConvexHull2d({{0, 0}, {3, 3}, {1, 1}, {2, 2}});
  EXPECT_EQ(line, std::vector<Eigen::Vector2d>({{0, 0}, {3, 3}}));
}

TEST(ConvexHull2d, EveryPointOfACloudIsInsideItsHull) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0, 1);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 5000; ++i) points.emplace_back(normal(random), 3 * normal(random));
  const std::vector<Eigen::Vector2d> hull = ConvexHull2d(points);
  ASSERT_GE(hull.size(), 3u);
  EXPECT_LT(hull.size(), 100u);
  for (const auto& p : points) {
    for (size_t i = 0; i < hull.size(); ++i) ASSERT_GE(Turn(hull[i], hull[(i + 1) % hull.size()], p), -1e-12);
  }
}

}  // namespace
}  // namespace urdfsnap::scene
