// Image comparison on small known images: statistics, bounding box, size mismatch, diff colours.
#include "image/image_diff.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"

namespace urdfsnap::image {
namespace {

// A width x height image of one colour.
Image Filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = r, image.rgb[i + 1] = g, image.rgb[i + 2] = b;
  }
  return image;
}

void SetPixel(Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* p = &image.rgb[3 * (std::size_t(y) * image.width + x)];
  p[0] = r, p[1] = g, p[2] = b;
}

TEST(CompareImagesTest, IdenticalImages) {
  const Image image = Filled(4, 3, 48, 48, 48);
  const DiffStats stats = CompareImages(image, image, 0);
  EXPECT_EQ(stats.max_delta, 0);
  EXPECT_EQ(stats.mean_delta, 0);
  EXPECT_EQ(stats.pixels_over, 0);
  EXPECT_EQ(stats.fraction_over, 0);
  EXPECT_EQ(stats.min_x, -1);
  EXPECT_EQ(stats.min_y, -1);
  EXPECT_EQ(stats.max_x, -1);
  EXPECT_EQ(stats.max_y, -1);
}

TEST(CompareImagesTest, KnownDifferences) {
  const Image expected = Filled(4, 3, 48, 48, 48);
  Image actual = expected;
  SetPixel(actual, 1, 0, 48, 58, 40);   // delta 10 (the largest channel difference)
  SetPixel(actual, 3, 2, 255, 48, 48);  // delta 207
  SetPixel(actual, 0, 1, 50, 48, 48);   // delta 2, under the threshold
  const DiffStats stats = CompareImages(expected, actual, 2);
  EXPECT_EQ(stats.max_delta, 207);
  EXPECT_DOUBLE_EQ(stats.mean_delta, (10 + 207 + 2) / 12.0);
  EXPECT_EQ(stats.pixels_over, 2);
  EXPECT_DOUBLE_EQ(stats.fraction_over, 2 / 12.0);
  EXPECT_EQ(stats.min_x, 1);
  EXPECT_EQ(stats.min_y, 0);
  EXPECT_EQ(stats.max_x, 3);
  EXPECT_EQ(stats.max_y, 2);
  // the threshold is exclusive: a delta equal to it is not over
  EXPECT_EQ(CompareImages(expected, actual, 10).pixels_over, 1);
  EXPECT_EQ(CompareImages(expected, actual, 1).pixels_over, 3);
}

TEST(CompareImagesTest, SizeMismatchNamesBothSizes) {
  try {
    CompareImages(Filled(640, 480, 0, 0, 0), Filled(320, 240, 0, 0, 0), 0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "image sizes differ: expected 640x480, actual 320x240");
  }
  EXPECT_THROW(MakeDiffImage(Filled(2, 2, 0, 0, 0), Filled(2, 3, 0, 0, 0), 0), Error);
}

TEST(CompareImagesTest, InconsistentImageIsAnError) {
  Image broken = Filled(2, 2, 0, 0, 0);
  broken.rgb.pop_back();
  EXPECT_THROW(CompareImages(Filled(2, 2, 0, 0, 0), broken, 0), Error);
}

TEST(MakeDiffImageTest, MagentaAndYellowOverDimmedGrey) {
  Image expected = Filled(4, 1, 0, 0, 0);
  SetPixel(expected, 1, 0, 255, 255, 255);
  SetPixel(expected, 2, 0, 255, 0, 0);
  Image actual = expected;
  SetPixel(actual, 2, 0, 0, 0, 0);
  SetPixel(actual, 3, 0, 0, 8, 0);
  const Image diff = MakeDiffImage(expected, actual, 8);
  EXPECT_EQ(diff.width, 4);
  EXPECT_EQ(diff.height, 1);
  // black -> 64, white -> 127 (luma squeezed into 64..127), the pixel changed by 255 magenta,
  // the one changed by 8 (not over the delta) yellow
  EXPECT_EQ(diff.rgb,
            (std::vector<std::uint8_t>{64, 64, 64, 127, 127, 127, 255, 0, 255, 255, 200, 0}));
}

// 100x100 images: the default tolerance allows 1 pixel in 10,000 over a delta of 8 and a mean of 0.1.
TEST(DiffToleranceTest, FractionAndMeanLimits) {
  const DiffTolerance tolerance;
  const Image expected = Filled(100, 100, 48, 48, 48);
  Image actual = expected;
  SetPixel(actual, 10, 20, 48, 48, 57);  // one pixel 9 over: at the fraction limit, still a match
  DiffStats stats = CompareImages(expected, actual, tolerance.max_delta);
  EXPECT_EQ(stats.pixels_over, 1);
  EXPECT_TRUE(WithinTolerance(stats, tolerance));
  SetPixel(actual, 11, 20, 48, 48, 57);  // a second one is too many
  EXPECT_FALSE(WithinTolerance(CompareImages(expected, actual, tolerance.max_delta), tolerance));
  // a faint change everywhere: no pixel over 8, but the mean delta of 5 is far over 0.1
  stats = CompareImages(expected, Filled(100, 100, 53, 48, 48), tolerance.max_delta);
  EXPECT_EQ(stats.pixels_over, 0);
  EXPECT_FALSE(WithinTolerance(stats, tolerance));
}

TEST(DiffToleranceTest, DescriptionHasTheFiguresAndTheRegion) {
  const Image expected = Filled(100, 100, 0, 0, 0);
  Image actual = expected;
  SetPixel(actual, 3, 4, 200, 0, 0);
  SetPixel(actual, 7, 9, 0, 100, 0);
  const DiffTolerance tolerance;
  EXPECT_EQ(DescribeDiff(CompareImages(expected, actual, 8), tolerance),
            "max delta 200, mean delta 0.030 (limit 0.1), 2 pixels (0.020%) over 8 (limit 0.01%), "
            "in x 3..7, y 4..9");
  EXPECT_EQ(DescribeDiff(CompareImages(expected, expected, 8), tolerance),
            "max delta 0, mean delta 0.000 (limit 0.1), 0 pixels (0.000%) over 8 (limit 0.01%)");
}

}  // namespace
}  // namespace urdfsnap::image
