// The drawing of scene::PointSet in RViz's five point-cloud styles: each style against its golden
// image (tests/golden/points_STYLE.png; URDFSNAP_UPDATE_GOLDENS=1 rewrites them, look at them
// after), and the rules of RViz's point-cloud materials by pixel: a flat square's colour, the
// outline of Squares, the shaded disc of Spheres, the per-face lightness of Boxes and their axes,
// the pixel size of Points, blending below alpha 1, no points in the label image, and the CPU
// splat drawing what GL draws.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "front_view.h"
#include "gl/internal/point_splat.h"
#include "image/image_diff.h"
#include "image/png_reader.h"
#include "image/png_writer.h"
#include "renderer_fixture.h"

namespace urdfsnap::gl {
namespace {

using scene::PointSet;
using Style = PointSet::Style;
using Rgb = std::array<int, 3>;

constexpr int kWidth = 160, kHeight = 120;

Rgb Pixel(const image::Image& image, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * image.width + x) * 3;
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// FrontView looks down -X from 2 m: the image plane is the world's YZ plane, +Y right, +Z up. One
// point at the origin of `size` in `rgba`.
PointSet OnePoint(Style style, float size, const Eigen::Vector4f& rgba) {
  PointSet points;
  points.style = style;
  points.size = Eigen::Vector3f::Constant(size);
  points.positions = {Eigen::Vector3f::Zero()};
  points.colours = {rgba};
  return points;
}

image::Image Draw(const PointSet& points, SceneRenderer& renderer) {
  scene::Scene scene;
  scene.points.push_back(points);
  return renderer.Render(scene, FrontView(), kWidth, kHeight).colour;
}

// A 7 x 5 lattice in the YZ plane, hues across and brightness down, a few points in front of others.
PointSet Lattice(Style style, float size) {
  PointSet points;
  points.style = style;
  points.size = Eigen::Vector3f::Constant(size);
  for (int row = 0; row < 5; ++row) {
    for (int column = 0; column < 7; ++column) {
      const float x = (row + column) % 3 == 0 ? 0.2f : 0.f;
      points.positions.emplace_back(x, -0.6f + 0.2f * column, -0.4f + 0.2f * row);
      const float v = 0.3f + 0.15f * row;
      points.colours.emplace_back(v * (column % 3 == 0), v * (column % 3 == 1), v * (column % 3 == 2 || column == 6), 1.f);
    }
  }
  return points;
}

using PointSetTest = RendererFixture;

TEST_F(PointSetTest, EachStyleMatchesItsGolden) {
  const std::pair<Style, std::string> styles[] = {{Style::kPoints, "points"},
                                                  {Style::kSquares, "squares"},
                                                  {Style::kFlatSquares, "flat_squares"},
                                                  {Style::kSpheres, "spheres"},
                                                  {Style::kBoxes, "boxes"}};
  for (const auto& [style, name] : styles) {
    const std::string style_name = name;
    const image::Image image = Draw(Lattice(style, style == Style::kPoints ? 6.f : 0.12f), *renderer_);
    const std::string golden = std::string(URDFSNAP_SOURCE_DIR) + "/tests/golden/points_" + style_name + ".png";
    if (const char* update = std::getenv("URDFSNAP_UPDATE_GOLDENS"); update && std::string(update) == "1") {
      image::WritePng(image, golden);
    }
    const image::DiffTolerance tolerance;
    const image::DiffStats stats = image::CompareImages(image::ReadPng(golden), image, tolerance.max_delta);
    EXPECT_TRUE(image::WithinTolerance(stats, tolerance)) << style_name << ": " << image::DescribeDiff(stats, tolerance);
  }
}

// Opaque camera-facing sets that GL would draw for PointSplat::kFewestPoints squares or more are splatted on the CPU,
// fewer drawn by GL: both draw the same pixels (to a level of rounding). The lattice alone goes through GL; with enough
// points out of sight (behind the camera) added, through the splat.
TEST_F(PointSetTest, SplatAndGlDrawTheSamePixels) {
  for (const Style style : {Style::kPoints, Style::kSquares, Style::kFlatSquares, Style::kSpheres}) {
    SCOPED_TRACE(static_cast<int>(style));
    const PointSet lattice = Lattice(style, style == Style::kPoints ? 6.f : 0.12f);
    PointSet padded = lattice;
    padded.positions.resize(3 * PointSplat::kFewestPoints, Eigen::Vector3f(5, 0, 0));   // GlCost >= kFewestPoints
    padded.colours.resize(padded.positions.size(), Eigen::Vector4f(1, 1, 1, 1));
    ASSERT_GE(PointSplat::GlCost(padded), PointSplat::kFewestPoints);
    const image::Image by_gl = Draw(lattice, *renderer_), splatted = Draw(padded, *renderer_);
    // the outlined and shaded styles may round a channel one level apart: the splat evaluates
    // point.frag's arithmetic in C++, llvmpipe in its own order
    const int allowed = style == Style::kSquares || style == Style::kSpheres ? 1 : 0;
    EXPECT_LE(image::CompareImages(by_gl, splatted, 0).max_delta, allowed);
  }
}

// 1 m at 2 m fills 72 pixels of the 120-pixel-high image (45 degrees): the centre pixel is the
// point's colour, and the outline of Squares (the outer 2-3%) about 1.5 pixels wide.
TEST_F(PointSetTest, FlatSquareIsItsColourAndSquaresHaveRVizOutline) {
  const image::Image flat = Draw(OnePoint(Style::kFlatSquares, 1.f, {1, 0.8f, 0.2f, 1}), *renderer_);
  EXPECT_EQ(Pixel(flat, kWidth / 2, kHeight / 2), (Rgb{255, 204, 51}));
  EXPECT_EQ(Pixel(flat, kWidth / 2 - 35, kHeight / 2), (Rgb{255, 204, 51}));
  // smooth_square.frag: the rim of a bright colour (|rgb| >= 0.5) is 0.2 darker
  const image::Image bright = Draw(OnePoint(Style::kSquares, 1.f, {1, 0.8f, 0.2f, 1}), *renderer_);
  EXPECT_EQ(Pixel(bright, kWidth / 2, kHeight / 2), (Rgb{255, 204, 51}));
  int darker_rim = 0;
  for (int x = kWidth / 2 - 40; x < kWidth / 2; ++x) {
    const Rgb rgb = Pixel(bright, x, kHeight / 2);
    if (rgb == Rgb{204, 153, 0}) ++darker_rim;
  }
  EXPECT_GE(darker_rim, 1);
  // ... and of a dark one 0.2 lighter
  const image::Image dark = Draw(OnePoint(Style::kSquares, 1.f, {0.2f, 0.1f, 0.1f, 1}), *renderer_);
  int lighter_rim = 0;
  for (int x = kWidth / 2 - 40; x < kWidth / 2; ++x) {
    if (Pixel(dark, x, kHeight / 2) == Rgb{102, 77, 77}) ++lighter_rim;
  }
  EXPECT_GE(lighter_rim, 1);
}

TEST_F(PointSetTest, SphereIsADiscDarkerAtItsRim) {
  const image::Image image = Draw(OnePoint(Style::kSpheres, 1.f, {0, 1, 0, 1}), *renderer_);
  EXPECT_EQ(Pixel(image, kWidth / 2, kHeight / 2), (Rgb{0, 255, 0}));
  // the square's corner (30 pixels out each way, 42 from the centre) is outside the disc of
  // radius 36 pixels: background
  EXPECT_EQ(Pixel(image, kWidth / 2 - 30, kHeight / 2 - 30), (Rgb{48, 48, 48}));
  // near the rim (33.5 pixels out) the colour falls towards 0.8 of the point's
  const Rgb rim = Pixel(image, kWidth / 2 - 34, kHeight / 2);
  EXPECT_GE(rim[1], 204);
  EXPECT_LT(rim[1], 230);
}

// box.geom's lightness: the +X face, which FrontView looks at, is 0.5 of the colour
TEST_F(PointSetTest, BoxFaceTowardsPlusXHasHalfTheColour) {
  const image::Image image = Draw(OnePoint(Style::kBoxes, 0.2f, {1, 1, 1, 1}), *renderer_);
  EXPECT_EQ(Pixel(image, kWidth / 2, kHeight / 2), (Rgb{128, 128, 128}));
}

// a white point of 5 pixels covers 25 pixels' worth of samples (partly covered pixels at its edges
// count by their share), within a 6 x 6 box
// boxes turned with their set's axes (45 degrees about Z) show the -y' face (0.4) on the left and
// the +x' face (0.5) on the right
TEST_F(PointSetTest, BoxesFollowTheSetsAxes) {
  PointSet points = OnePoint(Style::kBoxes, 0.4f, {1, 1, 1, 1});
  points.box_axes = Eigen::AngleAxisf(static_cast<float>(M_PI) / 4, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  const image::Image image = Draw(points, *renderer_);
  EXPECT_EQ(Pixel(image, kWidth / 2 - 6, kHeight / 2), (Rgb{102, 102, 102}));
  EXPECT_EQ(Pixel(image, kWidth / 2 + 6, kHeight / 2), (Rgb{128, 128, 128}));
}

// Opaque sets of one look (style, size, box axes) are drawn as one, whatever lies between them in
// the scene; each set keeps its own look: two white and green boxes of 0.2 m left and right, a red
// flat square between them and a blue box of 0.1 m above.
TEST_F(PointSetTest, SetsDrawnTogetherKeepTheirOwnLook) {
  const auto at = [](PointSet points, float y, float z) {
    points.positions = {{0, y, z}};
    return points;
  };
  scene::Scene scene;
  scene.points = {at(OnePoint(Style::kBoxes, 0.2f, {1, 1, 1, 1}), -0.5f, 0),
                  at(OnePoint(Style::kFlatSquares, 0.3f, {1, 0, 0, 1}), 0, 0),
                  at(OnePoint(Style::kBoxes, 0.2f, {0, 1, 0, 1}), 0.5f, 0),
                  at(OnePoint(Style::kBoxes, 0.1f, {0, 0, 1, 1}), 0, 0.5f)};
  const image::Image image = renderer_->Render(scene, FrontView(), kWidth, kHeight).colour;
  // FrontView at 160 x 120: 0.0138 m a pixel at 2 m, so the big boxes' front faces (1.9 m away)
  // are centred 38 pixels left and right of the centre and 15 wide, the small one's 37 above and 7
  EXPECT_EQ(Pixel(image, 42, 60), (Rgb{128, 128, 128}));
  EXPECT_EQ(Pixel(image, 42 + 4, 60), (Rgb{128, 128, 128}));
  EXPECT_EQ(Pixel(image, 80, 60), (Rgb{255, 0, 0}));
  EXPECT_EQ(Pixel(image, 118, 60), (Rgb{0, 128, 0}));
  EXPECT_EQ(Pixel(image, 80, 23), (Rgb{0, 0, 128}));
  EXPECT_EQ(Pixel(image, 80 + 6, 23), (Rgb{48, 48, 48}));   // beyond the small box
}

TEST_F(PointSetTest, PointsAreSquaresOfTheirSizeInPixels) {
  const image::Image image = Draw(OnePoint(Style::kPoints, 5.f, {1, 1, 1, 1}), *renderer_);
  double covered = 0;
  int min_x = kWidth, max_x = -1, min_y = kHeight, max_y = -1;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const int value = Pixel(image, x, y)[0];
      if (value == 48) continue;
      covered += (value - 48) / (255.0 - 48.0);
      min_x = std::min(min_x, x), max_x = std::max(max_x, x);
      min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    }
  }
  EXPECT_NEAR(covered, 25.0, 1.0);
  EXPECT_LE(max_x - min_x + 1, 6);
  EXPECT_LE(max_y - min_y + 1, 6);
}

TEST_F(PointSetTest, TranslucentPointsBlendOverWhatIsBehind) {
  const image::Image image = Draw(OnePoint(Style::kFlatSquares, 0.2f, {1, 1, 1, 0.5f}), *renderer_);
  const Rgb centre = Pixel(image, kWidth / 2, kHeight / 2);
  EXPECT_NEAR(centre[0], (255 + 48) / 2, 1);
}

TEST_F(PointSetTest, PointsAreNotInTheLabelImage) {
  scene::Scene scene;
  scene.points.push_back(OnePoint(Style::kBoxes, 0.4f, {1, 1, 1, 1}));
  image::FrameOutputs outputs;
  outputs.labels = true;
  const image::Frame frame = renderer_->Render(scene, FrontView(), kWidth, kHeight, outputs);
  for (std::uint16_t label : frame.labels.labels) ASSERT_EQ(label, 0);
}

}  // namespace
}  // namespace urdfsnap::gl
