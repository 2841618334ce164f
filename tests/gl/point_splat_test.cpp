// The CPU splat of opaque camera-facing points (gl/internal/point_splat.h), without GL: which
// samples a point's square covers, the nearest point winning, the tiles it reports, the shapes of
// shaders/point.frag, tiles on two threads, a square across tiles, a frame's tiles emptied for the
// next, a GL point placed as llvmpipe places it, the tiles written for the composite, and points
// behind the camera, off screen or not finite left out.
#include "gl/internal/point_splat.h"

#include <bit>
#include <limits>

#include <gtest/gtest.h>

namespace urdfsnap::gl {
namespace {

using scene::PointSet;
using Style = PointSet::Style;

constexpr int kWidth = 20, kHeight = 10;

// An orthographic view of 20 x 10 m looking down -Z: world (x, y) lands on window (x + 10, y + 5),
// the corner of pixels 9 and 10, 4 and 5,
// window depth 0.5 - z / 20 (the near and far planes at z = 10 and -10).
Eigen::Matrix4d Orthographic() {
  Eigen::Matrix4d P = Eigen::Matrix4d::Identity();
  P(0, 0) = 2.0 / kWidth;
  P(1, 1) = 2.0 / kHeight;
  P(2, 2) = -0.1;
  return P;
}

PointSet Points(Style style, float size, std::vector<Eigen::Vector3f> positions,
                const Eigen::Vector4f& rgba = {1, 0, 0, 1}) {
  PointSet points;
  points.style = style;
  points.size = Eigen::Vector3f::Constant(size);
  points.colours.assign(positions.size(), rgba);
  points.positions = std::move(positions);
  return points;
}

std::uint32_t Rgba(int r, int g, int b) { return r | g << 8 | b << 16 | 255u << 24; }

class PointSplatTest : public ::testing::Test {
 protected:
  void Splat(const PointSet& points, std::vector<Eigen::Vector2f> samples = {{0.5f, 0.5f}}) {
    splat.Clear(kWidth, kHeight, samples);
    splat.Add(points, Eigen::Matrix4d::Identity(), Orthographic());
    splat.Cover();
  }
  std::uint32_t Colour(int x, int y, int sample = 0) const { return splat.At(x, y, sample).colour; }
  float Depth(int x, int y, int sample = 0) const { return splat.At(x, y, sample).depth; }
  PointSplat splat;
};

TEST_F(PointSplatTest, APointOfThreePixelsCoversThreeByThreePixelCentres) {
  Splat(Points(Style::kPoints, 3, {{0, 0, 0}}));
  int covered = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) covered += Depth(x, y) != PointSplat::kEmpty;
  }
  EXPECT_EQ(covered, 9);   // the square [8.5, 11.5) x [3.5, 6.5): pixels 8..10 x 3..5
  EXPECT_EQ(Colour(8, 3), Rgba(255, 0, 0));
  EXPECT_EQ(Colour(10, 5), Rgba(255, 0, 0));
  EXPECT_EQ(Depth(11, 5), PointSplat::kEmpty);   // its centre 11.5 is on the excluded edge
  EXPECT_FLOAT_EQ(Depth(10, 5), 0.5f);
  EXPECT_EQ(splat.drawn(), std::vector<int>{0});   // the one tile of the image
}

TEST_F(PointSplatTest, EachSampleIsCoveredByItsOwnPosition) {
  // a 1 m flat square [9.5, 10.5) x [4.5, 5.5): pixel (9, 4) holds only the sample at (0.75, 0.75)
  Splat(Points(Style::kFlatSquares, 1, {{0, 0, 0}}), {{0.25f, 0.25f}, {0.75f, 0.75f}});
  EXPECT_EQ(Depth(9, 4, 0), PointSplat::kEmpty);
  EXPECT_NE(Depth(9, 4, 1), PointSplat::kEmpty);
  EXPECT_NE(Depth(10, 5, 0), PointSplat::kEmpty);
  EXPECT_EQ(Depth(10, 5, 1), PointSplat::kEmpty);
}

TEST_F(PointSplatTest, TheNearestPointWinsWhateverTheOrder) {
  for (const float first_z : {1.f, -1.f}) {
    PointSet points = Points(Style::kPoints, 1, {{0, 0, first_z}, {0, 0, -first_z}});
    points.colours = {{first_z > 0 ? 0.f : 1.f, 0, 1, 1}, {first_z > 0 ? 1.f : 0.f, 0, 1, 1}};
    Splat(points);
    EXPECT_EQ(Colour(9, 4), Rgba(0, 0, 255)) << "first z " << first_z;   // the point at z = +1
    EXPECT_FLOAT_EQ(Depth(9, 4), 0.45f);
  }
}

TEST_F(PointSplatTest, SquaresAreOutlinedAndSpheresShadedAsPointFragDoes) {
  // a 16 m square from x = 2: its middle keeps the colour; pixel 2 (u = 0.03125) is in the outline,
  // blend 0.316 between 0.6 and 0.6 - 0.2
  Splat(Points(Style::kSquares, 16, {{0, 0, 0}}, {0.6f, 0.6f, 0.6f, 1}));
  EXPECT_EQ(Colour(10, 5), Rgba(153, 153, 153));
  EXPECT_EQ(Colour(2, 5), Rgba(118, 118, 118));
  // a 4 m disc over pixels 8..11: pixel (9, 4) at u = v = 0.375 is 0.8 + 0.2 * 0.875 of white; the
  // corner pixel (8, 3) is outside the disc and left empty
  Splat(Points(Style::kSpheres, 4, {{0, 0, 0}}, {1, 1, 1, 1}));
  EXPECT_EQ(Colour(9, 4), Rgba(249, 249, 249));
  EXPECT_EQ(Depth(8, 3), PointSplat::kEmpty);
}

TEST_F(PointSplatTest, ManyPointsAreCoveredTileByTileOnTwoThreadsWithTheSameResult) {
  // 2 x 5,000 one-pixel points over a 100 x 50 image (4 x 2 tiles), the far red ones after the
  // near blue ones in one half and before them in the other: enough for a second thread; every
  // pixel is blue
  constexpr int kW = 100, kH = 50;
  Eigen::Matrix4d P = Orthographic();
  P(0, 0) = 2.0 / kW, P(1, 1) = 2.0 / kH;
  PointSet points = Points(Style::kPoints, 1, {});
  for (int i = 0; i < 2 * kW * kH; ++i) {
    const int pixel = i / 2, x = pixel % kW, y = pixel / kW;
    const bool near = (i % 2 == 0) == (y < kH / 2);
    points.positions.emplace_back(x + 0.5f - kW / 2.f, y + 0.5f - kH / 2.f, near ? 1.f : -1.f);
    points.colours.emplace_back(near ? 0.f : 1.f, 0, near ? 1.f : 0.f, 1);
  }
  ASSERT_GE(points.positions.size(), 2 * PointSplat::kSquaresPerThread);
  splat.Clear(kW, kH, {{0.5f, 0.5f}});
  splat.Add(points, Eigen::Matrix4d::Identity(), P);
  splat.Cover();
  int blue = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) blue += splat.At(x, y, 0).colour == Rgba(0, 0, 255);
  }
  EXPECT_EQ(blue, kW * kH);
  EXPECT_EQ(splat.drawn(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  const PointSplat::Tile last = splat.TileAt(7);   // the corner tile ends at the image's edges
  EXPECT_EQ(std::vector<int>({last.x0, last.y0, last.x1, last.y1}), std::vector<int>({96, 32, kW, kH}));
}

TEST_F(PointSplatTest, ASquareAcrossTilesIsCoveredInEachAndTheNextFrameStartsEmpty) {
  // a 6 m flat square at the middle of a 64 x 64 image (window [29, 35) each way): pixels 29..34,
  // in all four tiles of 32 x 32
  constexpr int kSide = 64;
  Eigen::Matrix4d P = Orthographic();
  P(0, 0) = P(1, 1) = 2.0 / kSide;
  splat.Clear(kSide, kSide, {{0.5f, 0.5f}});
  splat.Add(Points(Style::kFlatSquares, 6, {{0, 0, 0}}), Eigen::Matrix4d::Identity(), P);
  splat.Cover();
  EXPECT_EQ(splat.drawn(), (std::vector<int>{0, 1, 2, 3}));
  int covered = 0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) covered += splat.At(x, y, 0).depth != PointSplat::kEmpty;
  }
  EXPECT_EQ(covered, 36);
  EXPECT_EQ(splat.At(31, 31, 0).colour, Rgba(255, 0, 0));
  EXPECT_EQ(splat.At(32, 32, 0).colour, Rgba(255, 0, 0));
  // the next frame: a one-pixel point at window (10, 10), [9.5, 10.5): pixel 9 in the first tile
  // only; the square's samples there are gone, and the other tiles are not drawn
  splat.Clear(kSide, kSide, {{0.5f, 0.5f}});
  splat.Add(Points(Style::kPoints, 1, {{-22.f, -22.f, 0.f}}), Eigen::Matrix4d::Identity(), P);
  splat.Cover();
  EXPECT_EQ(splat.drawn(), std::vector<int>{0});
  EXPECT_EQ(splat.At(31, 31, 0).depth, PointSplat::kEmpty);
  EXPECT_EQ(splat.At(32, 32, 0).depth, PointSplat::kEmpty);
  EXPECT_NE(splat.At(9, 9, 0).depth, PointSplat::kEmpty);
}

TEST_F(PointSplatTest, SquaresOverManyTilesTieWithSmallOnesInTheOrderAdded) {
  // on a 96 x 96 image (3 x 3 tiles), at one depth: a one-pixel red point, a 60 m green square
  // [18, 78) over all nine tiles (kept aside as a big one), a one-pixel blue point; the later wins
  // each tie (GL_LEQUAL), as GL draws them
  constexpr int kSide = 96;
  Eigen::Matrix4d P = Orthographic();
  P(0, 0) = P(1, 1) = 2.0 / kSide;
  splat.Clear(kSide, kSide, {{0.5f, 0.5f}});
  splat.Add(Points(Style::kPoints, 1, {{-28.f, -28.f, 0.f}}, {1, 0, 0, 1}), Eigen::Matrix4d::Identity(), P);
  splat.Add(Points(Style::kFlatSquares, 60, {{0, 0, 0}}, {0, 1, 0, 1}), Eigen::Matrix4d::Identity(), P);
  splat.Add(Points(Style::kPoints, 1, {{28.f, 28.f, 0.f}}, {0, 0, 1, 1}), Eigen::Matrix4d::Identity(), P);
  splat.Cover();
  EXPECT_EQ(splat.drawn().size(), 9u);
  EXPECT_EQ(splat.At(19, 19, 0).colour, Rgba(0, 255, 0));   // red, then green over it
  EXPECT_EQ(splat.At(75, 75, 0).colour, Rgba(0, 0, 255));   // green, then blue
  EXPECT_EQ(splat.At(60, 30, 0).colour, Rgba(0, 255, 0));
  EXPECT_EQ(splat.At(90, 90, 0).depth, PointSplat::kEmpty);   // outside the square
}

TEST_F(PointSplatTest, ManyPointsOnOnePixelAtOneDepthLeaveTheLastOne) {
  // enough points for two threads: all red at one spot and depth but the last, blue; on a tie the
  // later wins, whichever thread covers the tile
  const std::vector<Eigen::Vector3f> origin(2 * PointSplat::kSquaresPerThread, Eigen::Vector3f::Zero());
  PointSet points = Points(Style::kPoints, 1, origin);
  points.colours.back() = {0, 0, 1, 1};
  Splat(points);
  EXPECT_EQ(Colour(9, 4), Rgba(0, 0, 255));
}

TEST_F(PointSplatTest, APointIsPlacedAsLlvmpipePlacesIt) {
  // lp_setup_point.c: the size and the centre snapped to 1/256 pixel, then x0 = centre - size / 2
  // (an integer division), x1 = x0 + size. 3.3 px is 845/256: a point at window (10, 5) spans
  // x [2138, 2983) / 256 = [8.3516, 11.6523), so a sample 0.65 into pixel 11 is in (snapping
  // each edge on its own would end it at 11.6484, leaving that column out)
  Splat(Points(Style::kPoints, 3.3f, {{0, 0, 0}}), {{0.65f, 0.5f}});
  int covered = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) covered += Depth(x, y) != PointSplat::kEmpty;
  }
  EXPECT_EQ(covered, 16);   // columns 8..11, rows 3..6 (y [3.3516, 6.6523) holds 3.5 .. 6.5)
  EXPECT_EQ(Colour(11, 5), Rgba(255, 0, 0));
  EXPECT_EQ(Depth(12, 5), PointSplat::kEmpty);
}

TEST_F(PointSplatTest, CoverWritesEachDrawnTileAsTheCompositeReadsIt) {
  // two samples on a 40 x 40 image (2 x 2 tiles, the right and top ones cut by its edges); points
  // in three tiles
  constexpr int kSide = 40;
  Eigen::Matrix4d P = Orthographic();
  P(0, 0) = P(1, 1) = 2.0 / kSide;
  splat.Clear(kSide, kSide, {{0.25f, 0.25f}, {0.75f, 0.75f}});
  splat.Add(Points(Style::kPoints, 3, {{-15, -15, 0}, {15, -15, 0.5f}, {-15, 15, -0.5f}}, {0, 1, 0, 1}),
            Eigen::Matrix4d::Identity(), P);
  std::vector<std::uint32_t> texels(splat.TexelWords(), 7);
  splat.Cover(texels.data());
  ASSERT_EQ(splat.drawn(), (std::vector<int>{0, 1, 2}));
  constexpr int kTile = PointSplat::kTileSize;
  for (const int tile : splat.drawn()) {
    const PointSplat::Tile rect = splat.TileAt(tile);
    for (int y = rect.y0; y < rect.y1; ++y) {
      for (int x = rect.x0; x < rect.x1; ++x) {
        for (int s = 0; s < 2; ++s) {
          // (depth, colour) of sample s at ((tile * samples + s) * kTile + y % kTile) * kTile + x % kTile
          const std::size_t pair = ((static_cast<std::size_t>(tile) * 2 + s) * kTile + y % kTile) * kTile + x % kTile;
          const PointSplat::Texel texel = splat.At(x, y, s);
          EXPECT_EQ(texels[2 * pair], std::bit_cast<std::uint32_t>(texel.depth)) << x << ", " << y << ", " << s;
          EXPECT_EQ(texels[2 * pair + 1], texel.colour) << x << ", " << y << ", " << s;
        }
      }
    }
  }
  EXPECT_EQ(splat.At(5, 5, 1).colour, Rgba(0, 255, 0));
  EXPECT_EQ(texels.back(), 7u);   // the fourth tile, not drawn, is not written
}

TEST_F(PointSplatTest, PointsOutsideTheViewOrNotFiniteAreLeftOutAndHugeOnesHeldToTheView) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  Splat(Points(Style::kPoints, 3, {{0, 0, 20}, {30, 0, 0}, {inf, 0, 0}, {nan, 0, 0}}));
  EXPECT_TRUE(splat.empty());
  // a square far bigger than the view covers all of it
  Splat(Points(Style::kFlatSquares, 1e12f, {{0, 0, 0}, {nan, 0, 0}}));
  EXPECT_EQ(Colour(0, 0), Rgba(255, 0, 0));
  EXPECT_EQ(Colour(kWidth - 1, kHeight - 1), Rgba(255, 0, 0));
}

}  // namespace
}  // namespace urdfsnap::gl
