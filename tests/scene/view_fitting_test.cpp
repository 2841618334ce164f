// --fit's view: the silhouette centred both ways and filling the frame up to the margin on its
// binding axis, the focal point kept when asked, and the scenes of an animation placed alike
// visited once (unit, no GL).
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

// The extents of the scene's vertices in normalised device coordinates seen through `view`: x
// from .min().x() to .max().x(), y likewise.
Eigen::AlignedBox2d NdcExtents(const Scene& scene, const OrbitView& view, double aspect) {
  const Eigen::Matrix4d PV = ProjectionMatrix(view, aspect) * ViewMatrix(view);
  Eigen::AlignedBox2d box;
  for (const auto& item : scene.items) {
    for (const auto& p : item.mesh->positions) {
      const Eigen::Vector4d clip = PV * (item.X_FG * p.cast<double>()).homogeneous();
      EXPECT_GT(clip.w(), 0);
      box.extend(Eigen::Vector2d(clip.x() / clip.w(), clip.y() / clip.w()));
    }
  }
  return box;
}

// The largest |NDC coordinate| of the scene's vertices seen through `view`.
double LargestNdc(const Scene& scene, const OrbitView& view, double aspect) {
  const Eigen::AlignedBox2d box = NdcExtents(scene, view, aspect);
  return std::max(box.max().cwiseAbs().maxCoeff(), box.min().cwiseAbs().maxCoeff());
}

Scene Joined(Scene a, const Scene& b) {
  a.items.insert(a.items.end(), b.items.begin(), b.items.end());
  return a;
}

TEST(FitView, CentresTheSilhouetteAndFillsTheFrameUpToTheMargin) {
  // a tall box and a small cube off to one side and below: the bounds' centre is not the centre
  // of what the camera sees
  Scene scene = CubeAt(Moved(1, 2, 3) * Eigen::Scaling(0.5, 0.5, 3.0));
  scene = Joined(scene, CubeAt(Moved(1, 4, 1) * Eigen::Scaling(0.2, 0.2, 0.2)));
  for (const double aspect : {4.0 / 3, 0.5}) {
    const OrbitView fitted = FitView(scene, OrbitView{}, aspect, false);
    const Eigen::AlignedBox2d box = NdcExtents(scene, fitted, aspect);
    EXPECT_NEAR(box.max().x(), -box.min().x(), 1e-6) << "centred across, aspect " << aspect;
    EXPECT_NEAR(box.max().y(), -box.min().y(), 1e-6) << "centred up and down, aspect " << aspect;
    // 5% of each side empty on the axis that binds, none past it on the other
    EXPECT_NEAR(std::max(box.max().x(), box.max().y()), 0.9, 1e-6);
    EXPECT_LE(std::min(box.max().x(), box.max().y()), 0.9 + 1e-6);
    // the same direction, and the focal point within the robot's depth
    EXPECT_EQ(fitted.yaw, OrbitView{}.yaw);
    EXPECT_EQ(fitted.pitch, OrbitView{}.pitch);
  }
}

TEST(FitView, TheMarginIsPerAxis) {
  const Scene scene = CubeAt(Moved(0, 0, 0));
  // square image, square-ish silhouette: a margin only across leaves the other axis at ±1
  const OrbitView across = FitView(scene, OrbitView{}, 1.0, false, {0.25, 0.0});
  const Eigen::AlignedBox2d box = NdcExtents(scene, across, 1.0);
  EXPECT_LE(box.max().x(), 0.5 + 1e-6);
  EXPECT_LE(box.max().y(), 1 + 1e-6);
  EXPECT_NEAR(std::max(box.max().x() / 0.5, box.max().y()), 1, 1e-6);
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
  EXPECT_EQ(asked, 6);   // each scene once
  const std::vector<Scene> distinct = {scenes[0], scenes[2], scenes[5]};
  const OrbitView once = FitView(3, [&](int k) { return distinct[k]; }, OrbitView{}, 1.0, false);
  EXPECT_EQ(all.focal, once.focal);
  EXPECT_EQ(all.distance, once.distance);
  EXPECT_TRUE(BoundsCentre(6, scene_of)->isApprox(Eigen::Vector3d(1, 1.5, 0), 1e-12));
  EXPECT_FALSE(BoundsCentre(1, [](int) { return Scene{}; }));
  // the same scene every frame (a still turntable) fits as that scene alone
  const OrbitView still = FitView(50, [&](int) { return scenes[2]; }, OrbitView{}, 1.0, false);
  const OrbitView one = FitView(scenes[2], OrbitView{}, 1.0, false);
  EXPECT_EQ(still.focal, one.focal);
  EXPECT_EQ(still.distance, one.distance);
}

// A turntable's distance: the largest of the per-yaw fits with the focal point kept, exactly (the
// same hulls, the same arithmetic), with a mesh's repeated corners counted once; no vertices, 0.
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
  // with a margin of its own on each axis (--fit-margin) too
  for (const FitMargin margin : {FitMargin{}, FitMargin{0.1, 0.2}}) {
    double widest = 0;
    for (const double yaw : yaws) {
      OrbitView side = view;
      side.yaw = yaw;
      widest = std::max(widest, FitView(scene, side, 4.0 / 3, true, margin).distance);
    }
    EXPECT_EQ(FitDistance(scene, view, yaws, 4.0 / 3, margin), widest);
  }
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
