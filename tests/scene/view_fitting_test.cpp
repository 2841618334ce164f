// --fit's view: the silhouette centred both ways and filling the frame up to the margin on its
// binding axis, the focal point kept when asked, and the scenes of an animation placed alike
// visited once (unit, no GL).
#include "scene/view_fitting.h"

#include <cmath>
#include <memory>
#include <random>

#include <gtest/gtest.h>

namespace urdfsnap::scene {
namespace {

// A scene of `mesh` placed at `X_FG`.
Scene MeshAt(std::shared_ptr<const geometry::TriangleMesh> mesh, const Eigen::Affine3d& X_FG) {
  Scene scene;
  DrawItem item;
  item.mesh = std::move(mesh);
  item.X_FG = X_FG;
  scene.items.push_back(item);
  return scene;
}

// A scene of one mesh of `points` (no triangles needed: the fit reads positions) placed at `X_FG`.
Scene PointsAt(const std::vector<Eigen::Vector3f>& points, const Eigen::Affine3d& X_FG) {
  auto mesh = std::make_shared<geometry::TriangleMesh>();
  mesh->positions = points;
  mesh->normals.assign(points.size(), Eigen::Vector3f(0, 0, 1));
  return MeshAt(mesh, X_FG);
}

// A scene of one unit cube's corners placed at `X_FG`.
Scene CubeAt(const Eigen::Affine3d& X_FG) {
  static const auto cube = [] {
    std::vector<Eigen::Vector3f> corners;
    for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f);
    return PointsAt(corners, Eigen::Affine3d::Identity()).items[0].mesh;
  }();
  return MeshAt(cube, X_FG);
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


// A turntable's distance with its points reduced to those near the 3-D hull is the brute force's
// (FitView at each yaw over every vertex) bit for bit: random clouds, dense grids on boxes
// (coplanar and collinear points, edge-on at yaw 0), cylinders' rings, several placed meshes, at
// several pitches and margins.
TEST(FitDistance, IsTheBruteForceFitOnRandomAndDegenerateSets) {
  std::mt19937 random(21);
  std::uniform_real_distribution<float> unit(-1, 1);
  std::uniform_real_distribution<double> angle(-3, 3);
  const auto cloud = [&](int n) {
    std::vector<Eigen::Vector3f> points;
    for (int i = 0; i < n; ++i) points.emplace_back(unit(random), unit(random), unit(random));
    return points;
  };
  std::vector<Eigen::Vector3f> grid;   // a box's surface and inside, on a grid of 0.25
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      for (int k = 0; k <= 4; ++k) grid.emplace_back(0.25f * i - 1, 0.25f * j - 1, 0.25f * k);
    }
  }
  std::vector<Eigen::Vector3f> cylinder;   // rings of 32 at 5 heights, and the axis
  for (int h = 0; h < 5; ++h) {
    for (int i = 0; i < 32; ++i) {
      const float a = static_cast<float>(i * 2 * M_PI / 32);
      cylinder.emplace_back(0.3f * std::cos(a), 0.3f * std::sin(a), 0.5f * h);
    }
    cylinder.emplace_back(0, 0, 0.5f * h);
  }
  std::vector<Scene> scenes = {PointsAt(cloud(400), Moved(0, 0, 0)), PointsAt(grid, Moved(0, 0, 0)),
                               PointsAt(grid, Moved(0.1, 0.2, 0.3) * Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())),
                               Joined(PointsAt(cylinder, Moved(0, 0, 0)), PointsAt(cylinder, Moved(0.5, 0.2, 1)))};
  Scene arm;   // several clouds placed along a bent arm, far from the origin
  for (int link = 0; link < 6; ++link) {
    arm = Joined(arm, PointsAt(cloud(150), Moved(100 + 0.3 * link, -50, 0.4 * link) *
                                               Eigen::AngleAxisd(angle(random), Eigen::Vector3d::UnitX()) *
                                               Eigen::Scaling(0.1, 0.1, 0.3)));
  }
  scenes.push_back(arm);
  for (size_t s = 0; s < scenes.size(); ++s) {
    for (const double pitch : {0.0, 0.785398, -0.4}) {
      OrbitView view;
      view.pitch = pitch;
      view.focal = *BoundsCentre(1, [&](int) { return scenes[s]; });
      std::vector<double> yaws;
      for (int k = 0; k < 24; ++k) yaws.push_back(k * 2 * M_PI / 24);
      for (const FitMargin margin : {FitMargin{}, FitMargin{0.1, 0.2}}) {
        double brute = 0;
        for (const double yaw : yaws) {
          OrbitView side = view;
          side.yaw = yaw;
          brute = std::max(brute, FitView(scenes[s], side, 4.0 / 3, true, margin).distance);
        }
        EXPECT_EQ(FitDistance(scenes[s], view, yaws, 4.0 / 3, margin), brute) << "scene " << s << " pitch " << pitch;
      }
    }
  }
}

}  // namespace
}  // namespace urdfsnap::scene
