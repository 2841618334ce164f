// The random samples: reproducible per (seed, index), within the joint limits, continuous joints
// over a full turn, mimics following; cameras on the sphere, looking at the centre, upright.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dataset/sampling.h"
#include "model/robot.h"

namespace urdfsnap::dataset {
namespace {

constexpr const char* kRobot = R"(<robot name="r">
  <link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <joint name="hinge" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-0.5" upper="1.5" effort="1" velocity="1"/></joint>
  <joint name="wheel" type="continuous"><parent link="b"/><child link="c"/></joint>
  <joint name="follower" type="revolute"><parent link="c"/><child link="d"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/><mimic joint="hinge" multiplier="2" offset="0.1"/></joint>
</robot>)";

TEST(Sampling, JointsWithinLimitsAndReproducible) {
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(kRobot, "r.urdf", warnings);
  double low_wheel = 10, high_wheel = -10;
  for (std::uint64_t k = 0; k < 400; ++k) {
    SampleRandom random(7, k);
    const std::vector<double> q = SampleJointPositions(robot, random, warnings);
    ASSERT_EQ(q.size(), 3u);
    EXPECT_GE(q[0], -0.5);
    EXPECT_LE(q[0], 1.5);
    EXPECT_GE(q[1], -std::numbers::pi);
    EXPECT_LT(q[1], std::numbers::pi);
    EXPECT_DOUBLE_EQ(q[2], 2 * q[0] + 0.1);
    low_wheel = std::min(low_wheel, q[1]);
    high_wheel = std::max(high_wheel, q[1]);
    SampleRandom again(7, k);
    EXPECT_EQ(SampleJointPositions(robot, again, warnings), q);
  }
  EXPECT_LT(low_wheel, -3.0);   // a full turn is covered
  EXPECT_GT(high_wheel, 3.0);
  SampleRandom other_seed(8, 0), first(7, 0);
  EXPECT_NE(other_seed.Next(), first.Next());
  EXPECT_TRUE(warnings.empty());
}

TEST(Sampling, CamerasLookAtTheCentreFromTheSphere) {
  const Eigen::Vector3d centre(0.3, -0.2, 0.8);
  for (std::uint64_t k = 0; k < 100; ++k) {
    SampleRandom random(1, k);
    const Eigen::Isometry3d X_WC = SampleCameraPose(centre, {2, 3}, {10, 50}, random);
    const Eigen::Vector3d towards = centre - X_WC.translation();
    EXPECT_GE(towards.norm(), 2 - 1e-12);
    EXPECT_LE(towards.norm(), 3 + 1e-12);
    // the optical axis points at the centre, x stays horizontal, y points down the image
    EXPECT_NEAR((X_WC.linear().col(2) - towards.normalized()).norm(), 0, 1e-12);
    EXPECT_NEAR(X_WC.linear().col(0).z(), 0, 1e-12);
    EXPECT_LT(X_WC.linear().col(1).z(), 0);
    EXPECT_NEAR(X_WC.linear().determinant(), 1, 1e-12);
    const double elevation = std::asin(-towards.normalized().z()) * 180 / std::numbers::pi;
    EXPECT_GE(elevation, 10 - 1e-9);
    EXPECT_LE(elevation, 50 + 1e-9);
  }
}

}  // namespace
}  // namespace urdfsnap::dataset
