// Depth and label comparison on hand-made 16-bit images: millimetre tolerance (exclusive), robot in
// one image only always differing, labels exact, the figures' line, and the pictures a report shows
// (false-colour depth, coloured labels, the diff colours).
#include "image/gray16_diff.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

#include "common/error.h"

namespace urdfsnap::image {
namespace {

// A width x height image of one value.
Gray16Image Filled(int width, int height, std::uint16_t value) {
  return Gray16Image{width, height, std::vector<std::uint16_t>(std::size_t(width) * height, value)};
}

void Set(Gray16Image& image, int x, int y, std::uint16_t value) { image.values[std::size_t(y) * image.width + x] = value; }

std::tuple<int, int, int> Pixel(const Image& image, int x, int y) {
  const std::uint8_t* p = &image.rgb[3 * (std::size_t(y) * image.width + x)];
  return {p[0], p[1], p[2]};
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CompareGray16Test, DepthWithinTheMillimetreToleranceMatches) {
  Gray16Image expected = Filled(5, 4, 1500);
  Set(expected, 0, 0, 0);  // no robot in either
  Gray16Image actual = expected;
  Set(actual, 1, 0, 1502);  // 2 mm: at the tolerance, not over it
  Set(actual, 2, 1, 1497);  // 3 mm
  Set(actual, 4, 3, 1400);  // 100 mm
  const Gray16DiffStats stats = CompareGray16(expected, actual, Gray16Kind::kDepth, 2);
  EXPECT_EQ(stats.max_delta, 100);
  EXPECT_EQ(stats.pixels_over, 2);
  EXPECT_EQ(stats.pixels_coverage, 0);
  EXPECT_DOUBLE_EQ(stats.fraction_over, 2 / 20.0);
  EXPECT_EQ(stats.min_x, 2);
  EXPECT_EQ(stats.min_y, 1);
  EXPECT_EQ(stats.max_x, 4);
  EXPECT_EQ(stats.max_y, 3);
  EXPECT_EQ(CompareGray16(expected, actual, Gray16Kind::kDepth, 3).pixels_over, 1);
  EXPECT_EQ(CompareGray16(expected, actual, Gray16Kind::kDepth, 1).pixels_over, 3);
  EXPECT_EQ(CompareGray16(expected, expected, Gray16Kind::kDepth, 0).pixels_over, 0);
  EXPECT_EQ(CompareGray16(expected, expected, Gray16Kind::kDepth, 0).min_x, -1);
}

TEST(CompareGray16Test, RobotInOneImageOnlyDiffersWhateverTheTolerance) {
  Gray16Image expected = Filled(3, 3, 0);
  Set(expected, 1, 1, 1);  // 1 mm: the nearest robot, next to "nothing" (0)
  Gray16Image actual = Filled(3, 3, 0);
  Set(actual, 2, 0, 900);
  const Gray16DiffStats stats = CompareGray16(expected, actual, Gray16Kind::kDepth, 65535);
  EXPECT_EQ(stats.pixels_over, 2);
  EXPECT_EQ(stats.pixels_coverage, 2);
  EXPECT_EQ(stats.max_delta, 0);  // no pixel has robot in both
  EXPECT_FALSE(WithinTolerance(stats, {65535, 0.1}));
  EXPECT_TRUE(WithinTolerance(stats, {0, 2 / 9.0}));
}

TEST(CompareGray16Test, LabelsAreComparedExactly) {
  Gray16Image expected = Filled(4, 2, 3);
  Gray16Image actual = expected;
  Set(actual, 0, 0, 4);  // the neighbouring link
  Set(actual, 3, 1, 0);  // nothing
  const Gray16DiffStats stats = CompareGray16(expected, actual, Gray16Kind::kLabels, 0);
  EXPECT_EQ(stats.pixels_over, 2);
  EXPECT_EQ(stats.pixels_coverage, 1);
  EXPECT_EQ(stats.max_delta, 0);
  EXPECT_FALSE(WithinTolerance(stats, DefaultTolerance(Gray16Kind::kLabels)));
  EXPECT_TRUE(WithinTolerance(CompareGray16(expected, expected, Gray16Kind::kLabels, 0),
                              DefaultTolerance(Gray16Kind::kLabels)));
  EXPECT_THROW(CompareGray16(expected, actual, Gray16Kind::kLabels, 1), Error);
}

TEST(CompareGray16Test, TheDefaultsAreTheMeasuredOnes) {
  EXPECT_EQ(DefaultTolerance(Gray16Kind::kDepth).max_delta, 2);
  EXPECT_DOUBLE_EQ(DefaultTolerance(Gray16Kind::kDepth).max_fraction, 0.0001);
  EXPECT_EQ(DefaultTolerance(Gray16Kind::kLabels).max_delta, 0);
  EXPECT_DOUBLE_EQ(DefaultTolerance(Gray16Kind::kLabels).max_fraction, 0);
}

TEST(CompareGray16Test, BadImagesNameTheProblem) {
  const Gray16Image a = Filled(4, 3, 1);
  try {
    CompareGray16(a, Filled(3, 4, 1), Gray16Kind::kDepth, 0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_TRUE(Contains(e.what(), "4x3")) << e.what();
    EXPECT_TRUE(Contains(e.what(), "3x4")) << e.what();
  }
  Gray16Image short_of_values = a;
  short_of_values.values.pop_back();
  EXPECT_THROW(CompareGray16(a, short_of_values, Gray16Kind::kDepth, 0), Error);
  EXPECT_THROW(CompareGray16(Gray16Image{}, Gray16Image{}, Gray16Kind::kDepth, 0), Error);
}

TEST(DescribeGray16DiffTest, DepthAndLabelLines) {
  Gray16Image expected = Filled(10, 10, 2000);
  Gray16Image actual = expected;
  Set(actual, 3, 4, 2012);
  Set(actual, 5, 6, 0);
  const Gray16DiffStats depth = CompareGray16(expected, actual, Gray16Kind::kDepth, 2);
  EXPECT_EQ(DescribeGray16Diff(depth, {2, 0.0001}, Gray16Kind::kDepth),
            "max delta 12 mm, 2 pixels (2.000%) over 2 mm (limit 0.01%), 1 of them robot in one image only, "
            "in x 3..5, y 4..6");
  const Gray16DiffStats labels = CompareGray16(Filled(10, 10, 1), Filled(10, 10, 1), Gray16Kind::kLabels, 0);
  EXPECT_EQ(DescribeGray16Diff(labels, {0, 0}, Gray16Kind::kLabels), "0 pixels (0.000%) differ (limit 0%)");
}

TEST(DepthPictureTest, NearIsYellowFarIsPurpleNothingIsBlack) {
  Gray16Image depth = Filled(3, 1, 0);
  Set(depth, 1, 0, 1000);
  Set(depth, 2, 0, 3000);
  const Image picture = DepthPicture(depth, 1000, 3000);
  EXPECT_EQ(Pixel(picture, 0, 0), std::make_tuple(0, 0, 0));
  EXPECT_EQ(Pixel(picture, 1, 0), std::make_tuple(253, 231, 37));
  EXPECT_EQ(Pixel(picture, 2, 0), std::make_tuple(68, 1, 84));
  int low = 0, high = 0;
  Gray16Image other = Filled(3, 1, 0);
  Set(other, 0, 0, 500);
  Gray16ValueRange(depth, other, low, high);
  EXPECT_EQ(low, 500);
  EXPECT_EQ(high, 3000);
  Gray16ValueRange(Filled(2, 2, 0), Filled(2, 2, 0), low, high);
  EXPECT_EQ(low, 1);
  EXPECT_EQ(high, 1);
  // one value everywhere (a flat face): still visible, not black
  EXPECT_NE(Pixel(DepthPicture(Filled(1, 1, 700), 700, 700), 0, 0), std::make_tuple(0, 0, 0));
}

TEST(LabelPictureTest, EveryLinkItsOwnColourNothingBlack) {
  Gray16Image labels = Filled(13, 1, 0);
  for (int x = 1; x < 13; ++x) Set(labels, x, 0, static_cast<std::uint16_t>(x));
  const Image picture = LabelPicture(labels);
  EXPECT_EQ(Pixel(picture, 0, 0), std::make_tuple(0, 0, 0));
  std::set<std::tuple<int, int, int>> colours;
  for (int x = 1; x < 13; ++x) {
    const auto colour = Pixel(picture, x, 0);
    const auto [r, g, b] = colour;
    EXPECT_GE(std::max({r, g, b}), 200) << x;  // bright: readable on the black background
    colours.insert(colour);
  }
  EXPECT_EQ(colours.size(), 12u);
  EXPECT_EQ(Pixel(LabelPicture(Filled(1, 1, 5)), 0, 0), Pixel(picture, 5, 0));  // same link, same colour
}

TEST(Gray16DiffImageTest, EachVerdictItsColourTheRestDimmedGrey) {
  Gray16Image expected = Filled(4, 1, 1000);
  Set(expected, 3, 0, 0);
  Gray16Image actual = expected;
  Set(actual, 0, 0, 1100);  // over
  Set(actual, 1, 0, 0);     // robot in one image only
  Set(actual, 2, 0, 1001);  // within
  const Image diff = MakeGray16DiffImage(expected, actual, 2, DepthPicture(expected, 1000, 1000));
  EXPECT_EQ(Pixel(diff, 0, 0), std::make_tuple(255, 0, 255));
  EXPECT_EQ(Pixel(diff, 1, 0), std::make_tuple(0, 255, 255));
  EXPECT_EQ(Pixel(diff, 2, 0), std::make_tuple(255, 200, 0));
  EXPECT_EQ(Pixel(diff, 3, 0), std::make_tuple(64, 64, 64));  // black (no robot), dimmed
  EXPECT_THROW(MakeGray16DiffImage(expected, actual, 2, Image{}), Error);
}

}  // namespace
}  // namespace urdfsnap::image
