// The depth and link-label images against geometry computed by hand: the depth of known faces at
// known pixels, the link there, nothing off the robot, transparent links included, grid and TF
// markers and text never in them, exact values (no multisample blend); dense meshes' drawn by the
// colour pass, at its first sample.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "gl/scene_renderer.h"
#include "front_view.h"
#include "renderer_fixture.h"
#include "scene/grid.h"
#include "scene/primitive_meshes.h"

namespace urdfsnap::gl {
namespace {

using namespace urdfsnap::scene;  // the scene vocabulary the renderer draws

constexpr int kWidth = 64, kHeight = 48;

DrawItem Box(int link, const Eigen::Vector3d& centre, const Eigen::Vector3d& size, float alpha = 1) {
  DrawItem item;
  item.mesh = UnitBoxMesh();
  item.X_FG = Eigen::Translation3d(centre) * Eigen::Scaling(size);
  item.rgba = {1, 0, 0, alpha};
  item.link = link;
  return item;
}

float DepthAt(const image::Frame& frame, int x, int y) { return frame.depth.metres[y * kWidth + x]; }
int LabelAt(const image::Frame& frame, int x, int y) { return frame.labels.labels[y * kWidth + x]; }

class FrameOutputsTest : public RendererFixture {
 protected:
  image::Frame Render(const Scene& scene) {
    return renderer_->Render(scene, FrontView(), kWidth, kHeight, {true, true, true});
  }
};

TEST_F(FrameOutputsTest, FaceFacingTheCameraHasItsDistanceAndLinkOffTheRobotNothing) {
  Scene scene;
  scene.items.push_back(Box(2, {0, 0, 0}, {1, 1, 1}));
  const image::Frame frame = Render(scene);
  ASSERT_EQ(frame.depth.width, kWidth);
  ASSERT_EQ(frame.labels.height, kHeight);
  // the face at x = 0.5 is 1.5 m from the eye along the axis, wherever it is seen
  for (const auto& [x, y] : {std::pair{32, 24}, {25, 20}, {40, 30}}) {
    EXPECT_NEAR(DepthAt(frame, x, y), 1.5f, 1e-5f) << x << "," << y;
    EXPECT_EQ(LabelAt(frame, x, y), 3) << x << "," << y;   // 1 + link index 2
  }
  // the face spans ±0.5 m at 1.5 m: ±0.5 / (1.5 · tan 22.5° · 4/3) · 32 = ±19.3 columns from the
  // centre line, so the centres of columns 50 (18.5 away) and 13 are on it, 51 and 12 are not
  EXPECT_EQ(LabelAt(frame, 50, 24), 3);
  EXPECT_EQ(LabelAt(frame, 51, 24), 0);
  EXPECT_EQ(LabelAt(frame, 13, 24), 3);
  EXPECT_EQ(LabelAt(frame, 12, 24), 0);
  for (const auto& [x, y] : {std::pair{0, 0}, {63, 47}, {2, 24}}) {
    EXPECT_TRUE(std::isnan(DepthAt(frame, x, y))) << x << "," << y;
    EXPECT_EQ(LabelAt(frame, x, y), 0) << x << "," << y;
  }
}

TEST_F(FrameOutputsTest, SlantedFaceHasTheRayDistanceAtEachPixel) {
  // a quad in the plane x = 0.2 z facing the camera; the ray through pixel (px, py) is
  // eye + s·(-1, u·tx, v·ty) with s the distance along the axis, so 2 - s = 0.2 · s · v · ty
  geometry::TriangleMesh quad;
  quad.positions = {{-0.2f, -1, -1}, {-0.2f, 1, -1}, {0.2f, 1, 1}, {0.2f, -1, 1}};
  quad.normals.assign(4, Eigen::Vector3f(1, 0, -0.2f).normalized());
  quad.indices = {0, 1, 2, 0, 2, 3};
  DrawItem item;
  item.mesh = std::make_shared<const geometry::TriangleMesh>(quad);
  item.X_FG = Eigen::Affine3d::Identity();
  item.link = 0;
  Scene scene;
  scene.items.push_back(item);
  const image::Frame frame = Render(scene);
  const double ty = std::tan(FrontView().fov_y / 2);
  for (int py : {8, 20, 24, 31, 40}) {
    const double v = 1 - 2 * (py + 0.5) / kHeight;
    const double s = 2 / (1 + 0.2 * v * ty);
    EXPECT_NEAR(DepthAt(frame, 32, py), s, 1e-4) << "row " << py;
    EXPECT_EQ(LabelAt(frame, 32, py), 1);
  }
}

TEST_F(FrameOutputsTest, NearestLinkWinsTransparentOnesCountMarkersGridAndTextDoNot) {
  Scene scene;
  scene.items.push_back(Box(0, {0, 0, 0}, {1, 1, 1}));
  // a half-transparent link in front of the centre: it is robot geometry, so it is in both images
  scene.items.push_back(Box(4, {0.9, 0, 0}, {0.1, 0.2, 0.2}, 0.5f));
  // a TF marker part in front of the right half and the grid: never in them
  DrawItem marker = Box(-1, {1.2, 0.15, 0}, {0.1, 0.3, 0.3});
  scene.items.push_back(marker);
  scene.lines.push_back(MakeGrid({}));
  const image::Frame frame = Render(scene);
  EXPECT_EQ(LabelAt(frame, 32, 24), 5);
  EXPECT_NEAR(DepthAt(frame, 32, 24), 2 - 0.95, 1e-5);
  // where only the marker is in front (y = 0.15 m at 0.75 m: column 43), the box's face is what the
  // images show
  const int marker_x = 32 + static_cast<int>(0.15 / (0.75 * std::tan(FrontView().fov_y / 2) * 4 / 3) * 32);
  ASSERT_EQ(marker_x, 43);
  EXPECT_EQ(LabelAt(frame, marker_x, 24), 1);
  EXPECT_NEAR(DepthAt(frame, marker_x, 24), 1.5, 1e-5);
  // and the colour image does show the marker there
  const auto& rgb = frame.colour.rgb;
  EXPECT_GT(rgb[(24 * kWidth + marker_x) * 3], 200);
}

TEST_F(FrameOutputsTest, ValuesAreExactAtEdgesAndOnlyWhatIsAskedForIsMade) {
  Scene scene;
  scene.items.push_back(Box(0, {0, 0, 0}, {1, 1, 1}));
  scene.items.push_back(Box(1, {0.6, 0.25, 0}, {0.2, 0.5, 0.5}));
  const image::Frame frame = Render(scene);
  for (std::uint16_t label : frame.labels.labels) EXPECT_TRUE(label <= 2);
  // every depth is one of the two faces' (no blend between them or with the background)
  for (size_t i = 0; i < frame.depth.metres.size(); ++i) {
    const float d = frame.depth.metres[i];
    const int label = frame.labels.labels[i];
    if (label == 0) {
      EXPECT_TRUE(std::isnan(d));
    } else {
      EXPECT_NEAR(d, label == 1 ? 1.5f : 1.3f, 1e-5f);
    }
  }
  const image::Frame colour_only = renderer_->Render(scene, FrontView(), kWidth, kHeight);
  EXPECT_EQ(colour_only.colour.rgb, frame.colour.rgb);
  EXPECT_TRUE(colour_only.depth.metres.empty());
  EXPECT_TRUE(colour_only.labels.labels.empty());
  const image::Frame labels_only = renderer_->Render(scene, FrontView(), kWidth, kHeight, {false, false, true});
  EXPECT_TRUE(labels_only.colour.rgb.empty());
  EXPECT_EQ(labels_only.labels.labels, frame.labels.labels);
}

// A square of 2·n·n triangles in the plane x = 0.2 z, y and z in [-0.5, 0.5], facing the camera.
geometry::TriangleMesh DenseSlantedSquare(int n) {
  geometry::TriangleMesh square;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const float y = -0.5f + static_cast<float>(i) / n, z = -0.5f + static_cast<float>(j) / n;
      square.positions.emplace_back(0.2f * z, y, z);
      square.normals.push_back(Eigen::Vector3f(1, 0, -0.2f).normalized());
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const auto corner = static_cast<std::uint32_t>(i * (n + 1) + j);
      square.indices.insert(square.indices.end(),
                            {corner, corner + n + 1, corner + n + 2, corner, corner + n + 2, corner + 1});
    }
  }
  return square;
}

// A dense square (800 triangles on 64x48 pixels: a triangle per 8 pixels or more, so the colour
// pass draws the labels and depths too) 0.3 m behind the image plane of FrontView, link 1, in
// front of a box, link 0.
Scene DenseScene() {
  DrawItem square;
  square.mesh = std::make_shared<const geometry::TriangleMesh>(DenseSlantedSquare(20));
  square.X_FG = Eigen::Translation3d(-0.3, 0, 0);
  square.rgba = {0, 1, 0, 1};
  square.link = 1;
  Scene scene;
  scene.items.push_back(Box(0, {-0.8, 0, 0}, {0.2, 2, 2}));
  scene.items.push_back(square);
  return scene;
}

TEST_F(FrameOutputsTest, DenseMeshesTakeLabelsAndDepthFromTheColourPassDifferingOnlyOnOutlines) {
  const Scene scene = DenseScene();
  const image::Frame one_draw = Render(scene);
  // without the colour image they have a pass of their own, sampling pixel centres
  const image::Frame own_pass = renderer_->Render(scene, FrontView(), kWidth, kHeight, {false, true, true});
  int outline = 0, moved = 0;
  for (int y = 1; y < kHeight - 1; ++y) {
    for (int x = 1; x < kWidth - 1; ++x) {
      const int centre = LabelAt(own_pass, x, y);
      bool interior = true;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) interior = interior && LabelAt(own_pass, x + dx, y + dy) == centre;
      }
      outline += interior ? 0 : 1;
      const int label = LabelAt(one_draw, x, y);
      if (label != centre) {
        ++moved;
        EXPECT_FALSE(interior) << x << "," << y;
      } else if (interior && label != 0) {
        EXPECT_NEAR(DepthAt(one_draw, x, y), DepthAt(own_pass, x, y), 1e-4f) << x << "," << y;
      }
      if (label == 0) {
        EXPECT_TRUE(std::isnan(DepthAt(one_draw, x, y))) << x << "," << y;
      }
    }
  }
  EXPECT_GT(moved, 0);
  EXPECT_LT(moved, outline);
  EXPECT_EQ(LabelAt(one_draw, 32, 24), 2);
  EXPECT_EQ(LabelAt(one_draw, 32, 5), 1);   // the box above the square
}

TEST_F(FrameOutputsTest, DenseMeshesLabelsAreThoseAtTheFirstSampleOfEachPixel) {
  // llvmpipe's first sample lies at (0.375, 0.125) of a pixel from its top left corner (see
  // RendererTest.MultisamplesLieWhereTheyLieInRvizsWindow): a link covering only the upper left
  // eighth of pixel (32, 24) is that pixel's label, one covering only its lower right eighth is
  // not; a pass of their own sees neither (the centre is the square's)
  const auto label_at_32_24 = [&](double x0, double x1, double y0, double y1, const image::FrameOutputs& outputs) {
    Scene scene = DenseScene();
    scene.items.push_back(ImageRectangle(x0, x1, y0, y1));
    scene.items.back().link = 4;
    return LabelAt(renderer_->Render(scene, FrontView(), kWidth, kHeight, outputs), 32, 24);
  };
  const image::FrameOutputs all{true, true, true}, no_colour{false, true, true};
  EXPECT_EQ(label_at_32_24(32, 32.5, 24, 24.25, all), 5);
  EXPECT_EQ(label_at_32_24(32.5, 33, 24.75, 25, all), 2);
  EXPECT_EQ(label_at_32_24(32, 32.5, 24, 24.25, no_colour), 2);
  EXPECT_EQ(label_at_32_24(32.5, 33, 24.75, 25, no_colour), 2);
}

}  // namespace
}  // namespace urdfsnap::gl
