// RViz's orbit camera: eye placement, look-at and projection (unit, no GL).
#include "scene/orbit_view.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace urdfsnap::scene {
namespace {

Eigen::Vector2d ProjectToPixels(const OrbitView& view, const Eigen::Vector3d& p, int w, int h) {
  const Eigen::Vector4d clip =
      ProjectionMatrix(view, double(w) / h) * ViewMatrix(view) * p.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return {(ndc.x() + 1) / 2 * w, (1 - ndc.y()) / 2 * h};
}

TEST(OrbitView, DefaultEyeIsRvizs) {
  const OrbitView view;
  const double c = std::cos(0.785398);
  const double s = std::sin(0.785398);
  EXPECT_TRUE(EyePosition(view).isApprox(10 * Eigen::Vector3d(c * c, s * c, s), 1e-12));
}

TEST(OrbitView, YawZeroLooksFromPlusX) {
  OrbitView view;
  view.yaw = 0;
  view.pitch = 0;
  view.distance = 3;
  view.focal = {1, 2, 3};
  EXPECT_TRUE(EyePosition(view).isApprox(Eigen::Vector3d(4, 2, 3)));
  // looking along -X with +Z up, the world +Y is on the image's right
  const Eigen::Vector2d right = ProjectToPixels(view, {1, 2.5, 3}, 640, 480);
  EXPECT_GT(right.x(), 320);
  const Eigen::Vector2d up = ProjectToPixels(view, {1, 2, 3.5}, 640, 480);
  EXPECT_LT(up.y(), 240);  // +Z is up in the image
}

TEST(OrbitView, FocalPointProjectsToImageCentre) {
  OrbitView view;
  view.yaw = 0.6;
  view.pitch = 0.35;
  view.distance = 4.5;
  view.focal = {0, 0, 1.2};
  const Eigen::Vector2d centre = ProjectToPixels(view, view.focal, 640, 480);
  EXPECT_NEAR(centre.x(), 320, 1e-9);
  EXPECT_NEAR(centre.y(), 240, 1e-9);
}

TEST(OrbitView, VerticalFieldOfViewSpansImageHeight) {
  OrbitView view;
  view.yaw = 0;
  view.pitch = 0;
  view.distance = 1;
  // a point at the top edge of a 45° frustum, one metre in front of the eye
  const double top = std::tan(std::numbers::pi / 8);
  const Eigen::Vector2d p = ProjectToPixels(view, {0, 0, top}, 640, 480);
  EXPECT_NEAR(p.y(), 0, 1e-9);
}

TEST(OrbitView, PitchIsKeptOffThePoles) {
  OrbitView view;
  view.pitch = 2.0;
  view.distance = 1;
  view.yaw = 0;
  const double limit = std::numbers::pi / 2 - 0.001;
  EXPECT_NEAR(EyePosition(view).z(), std::sin(limit), 1e-12);
  EXPECT_TRUE(ViewMatrix(view).allFinite());
}

}  // namespace
}  // namespace urdfsnap::scene
