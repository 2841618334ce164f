// --fit's view: every vertex inside the image with the margin, the focal point at the centre of
// the bounds, and the scenes of an animation placed alike visited once (unit, no GL).
#include "scene/view_fitting.h"

#include <memory>

#include <gtest/gtest.h>

namespace urdfsnap::scene {
namespace {

// A scene of one unit cube's corners placed at `X_FG`.
Scene CubeAt(const Eigen::Affine3d& X_FG) {
  static const auto cube = [] {
    auto mesh = std::make_shared<geometry::TriangleMesh>();
    for (int i = 0; i < 8; ++i) {
      mesh->positions.emplace_back(i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f);
      mesh->normals.emplace_back(0, 0, 1);
    }
    return std::shared_ptr<const geometry::TriangleMesh>(mesh);
  }();
  Scene scene;
  DrawItem item;
  item.mesh = cube;
  item.X_FG = X_FG;
  scene.items.push_back(item);
  return scene;
}

Eigen::Affine3d Moved(double x, double y, double z) { return Eigen::Affine3d(Eigen::Translation3d(x, y, z)); }

// The largest |NDC coordinate| of the scene's vertices seen through `view`.
double LargestNdc(const Scene& scene, const OrbitView& view, double aspect) {
  const Eigen::Matrix4d PV = ProjectionMatrix(view, aspect) * ViewMatrix(view);
  double largest = 0;
  for (const auto& item : scene.items) {
    for (const auto& p : item.mesh->positions) {
      const Eigen::Vector4d clip = PV * (item.X_FG * p.cast<double>()).homogeneous();
      largest = std::max({largest, std::abs(clip.x() / clip.w()), std::abs(clip.y() / clip.w())});
    }
  }
  return largest;
}

TEST(FitView, FramesEveryVertexWithTheMargin) {
  const Scene scene = CubeAt(Moved(1, 2, 3));
  const OrbitView fitted = FitView(scene, OrbitView{}, 4.0 / 3, false);
  EXPECT_TRUE(fitted.focal.isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  // the outermost vertex touches the shrunk frame (within rounding), none goes past it
  EXPECT_NEAR(LargestNdc(scene, fitted, 4.0 / 3), 0.9, 1e-9);
}

TEST(FitView, KeepsTheFocalPointWhenAsked) {
  const Scene scene = CubeAt(Moved(1, 0, 0));
  OrbitView view;
  view.focal = {0, 0, 0};
  const OrbitView fitted = FitView(scene, view, 1.0, true);
  EXPECT_EQ(fitted.focal, view.focal);
  EXPECT_LE(LargestNdc(scene, fitted, 1.0), 0.9 + 1e-9);
  EXPECT_GT(LargestNdc(scene, fitted, 1.0), 0.89);
}

TEST(FitView, NoVerticesLeavesTheViewAlone) {
  OrbitView view;
  view.distance = 7;
  for (const bool keep_focal : {false, true}) {
    const OrbitView fitted = FitView(Scene{}, view, 1.0, keep_focal);
    EXPECT_EQ(fitted.distance, 7);
    EXPECT_EQ(fitted.focal, view.focal);
  }
}

// Scenes placed as the one before them are skipped; a scene that differs again after them, or a
// repeat of an earlier one further back, still counts in full.
TEST(FitView, RepeatedScenesFitAsOnce) {
  const std::vector<Scene> scenes = {CubeAt(Moved(0, 0, 0)), CubeAt(Moved(0, 0, 0)), CubeAt(Moved(2, 0, 0)),
                                     CubeAt(Moved(2, 0, 0)), CubeAt(Moved(0, 0, 0)), CubeAt(Moved(0, 3, 0))};
  int asked = 0;
  const auto scene_of = [&](int k) {
    ++asked;
    return scenes[k];
  };
  const OrbitView all = FitView(6, scene_of, OrbitView{}, 1.0, false);
  EXPECT_EQ(asked, 12);   // bounds, then distance
  const std::vector<Scene> distinct = {scenes[0], scenes[2], scenes[5]};
  const OrbitView once = FitView(3, [&](int k) { return distinct[k]; }, OrbitView{}, 1.0, false);
  EXPECT_EQ(all.focal, once.focal);
  EXPECT_EQ(all.distance, once.distance);
  EXPECT_TRUE(all.focal.isApprox(Eigen::Vector3d(1, 1.5, 0), 1e-12));
  // the same scene every frame (a still turntable) fits as that scene alone
  const OrbitView still = FitView(50, [&](int) { return scenes[2]; }, OrbitView{}, 1.0, false);
  const OrbitView one = FitView(scenes[2], OrbitView{}, 1.0, false);
  EXPECT_EQ(still.focal, one.focal);
  EXPECT_EQ(still.distance, one.distance);
}

// A turntable's distance: the largest of the per-yaw fits, exactly (the same vertices, the same
// arithmetic), with a mesh's repeated corners counted once; no vertices, 0.
TEST(FitDistance, IsTheLargestFitOverTheYaws) {
  Scene scene = CubeAt(Moved(1, 0.5, 0));
  auto repeated = std::make_shared<geometry::TriangleMesh>(*scene.items[0].mesh);
  repeated->positions.insert(repeated->positions.end(), repeated->positions.begin(), repeated->positions.end());
  scene.items.push_back(scene.items[0]);
  scene.items[1].mesh = repeated;
  scene.items[1].X_FG = Moved(-1, 0, 0.25);
  OrbitView view;
  view.focal = {0.2, 0, 0};
  const std::vector<double> yaws = {0, 0.7, 1.9, 3.1, 4.4};
  double largest = 0;
  for (const double yaw : yaws) {
    OrbitView side = view;
    side.yaw = yaw;
    largest = std::max(largest, FitView(scene, side, 4.0 / 3, true).distance);
  }
  EXPECT_EQ(FitDistance(scene, view, yaws, 4.0 / 3), largest);
  EXPECT_GT(largest, FitView(scene, view, 4.0 / 3, true).distance);   // some yaw needs more room
  EXPECT_EQ(FitDistance(Scene{}, view, yaws, 4.0 / 3), 0);
}

}  // namespace
}  // namespace urdfsnap::scene
