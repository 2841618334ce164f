// GL plumbing by exact pixels (after MuJoCo's render test): cleared background, a lit triangle
// facing the camera, row order of the read-back, and the grid's blended line colour.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include "render/grid.h"

namespace urdfsnap::render {
namespace {

using Rgb = std::array<int, 3>;

Rgb Pixel(const image::Image& image, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * image.width + x) * 3;
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// Looking down -X at the origin from 2 m away: the image plane is the world's YZ plane.
OrbitView FrontView() {
  OrbitView view;
  view.yaw = 0;
  view.pitch = 0;
  view.distance = 2;
  return view;
}

// One triangle in the x = 0 plane, facing +X (the camera), covering the upper part of the view.
std::shared_ptr<const geometry::TriangleMesh> UpperTriangle() {
  geometry::TriangleMesh mesh;
  mesh.positions = {{0, -0.3f, 0.1f}, {0, 0.3f, 0.1f}, {0, 0, 0.6f}};
  mesh.normals.assign(3, Eigen::Vector3f::UnitX());
  mesh.indices = {0, 1, 2};
  return std::make_shared<const geometry::TriangleMesh>(mesh);
}

class RendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { renderer_ = new Renderer(4); }
  static void TearDownTestSuite() { delete renderer_; }
  static Renderer* renderer_;
};
Renderer* RendererTest::renderer_ = nullptr;

TEST_F(RendererTest, EmptySceneIsTheBackgroundEverywhere) {
  Scene scene;
  scene.background = {48 / 255.f, 48 / 255.f, 48 / 255.f};
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48);
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) ASSERT_EQ(Pixel(image, x, y), (Rgb{48, 48, 48})) << x << "," << y;
  }
}

TEST_F(RendererTest, TriangleFacingTheLightHasItsFullColourAndTopRowComesFirst) {
  Scene scene;
  DrawItem item;
  item.mesh = UpperTriangle();
  item.X_FG = Eigen::Affine3d::Identity();
  item.rgba = {1, 0.2f, 0, 1};
  scene.items.push_back(item);
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48);
  // n · l = 1, so the colour is exactly the diffuse colour (0.2 · 255 = 51)
  EXPECT_EQ(Pixel(image, 32, 14), (Rgb{255, 51, 0}));
  // the triangle is above the centre, so the bottom rows are background
  EXPECT_EQ(Pixel(image, 32, 40), (Rgb{48, 48, 48}));
  EXPECT_EQ(Pixel(image, 2, 2), (Rgb{48, 48, 48}));
}

TEST_F(RendererTest, BackFacesAreCulled) {
  Scene scene;
  DrawItem item;
  item.mesh = UpperTriangle();
  item.X_FG = Eigen::AngleAxisd(3.14159265358979, Eigen::Vector3d::UnitZ()) * Eigen::Affine3d::Identity();
  scene.items.push_back(item);
  const image::Image image = renderer_->Render(scene, FrontView(), 64, 48);
  EXPECT_EQ(Pixel(image, 32, 14), (Rgb{48, 48, 48}));
}

TEST_F(RendererTest, GridLinesBlendAtHalfAlphaAsRvizMeasured) {
  Renderer no_aa(0);
  Scene scene;
  scene.lines.push_back(MakeGrid({}));
  OrbitView top;
  top.pitch = 1.5;
  top.distance = 12;
  const image::Image image = no_aa.Render(scene, top, 320, 240);
  // without multisampling a line pixel has full coverage: 0.5·(160,160,164) + 0.5·48, and where
  // two lines cross the second blends over the first
  const Rgb line{104, 104, 106}, crossing{132, 132, 135}, background{48, 48, 48};
  int line_pixels = 0, crossings = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Rgb p = Pixel(image, x, y);
      line_pixels += p == line;
      crossings += p == crossing;
      ASSERT_TRUE(p == line || p == crossing || p == background) << x << "," << y;
    }
  }
  EXPECT_GT(line_pixels, 1000);
  EXPECT_GT(crossings, 0);
}

}  // namespace
}  // namespace urdfsnap::render
