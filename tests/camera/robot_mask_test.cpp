// The robot mask and its dilation (a disc of radius N pixels), and the camera-image underlay over
// all that was drawn.
#include <gtest/gtest.h>

#include "camera/robot_mask.h"
#include "camera/underlay.h"
#include "support/error_text.h"

namespace urdfsnap::camera {
namespace {

image::LabelImage OnePixel(int w, int h, int x, int y) {
  image::LabelImage labels{w, h, std::vector<std::uint16_t>(static_cast<size_t>(w) * h, 0)};
  labels.labels[static_cast<size_t>(y) * w + x] = 3;
  return labels;
}

TEST(RobotMask, WithoutDilationIsTheRobotsPixels) {
  const image::Gray8Image mask = RobotMask(OnePixel(5, 4, 2, 1), 0);
  ASSERT_EQ(mask.values.size(), 20u);
  for (size_t i = 0; i < 20; ++i) EXPECT_EQ(mask.values[i], i == 7 ? 255 : 0);
}

TEST(RobotMask, DilationGrowsADiscOfRadiusN) {
  const int n = 5, w = 21, h = 17, cx = 10, cy = 8;
  const image::Gray8Image mask = RobotMask(OnePixel(w, h, cx, cy), n);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool inside = (x - cx) * (x - cx) + (y - cy) * (y - cy) <= n * n;
      EXPECT_EQ(mask.values[static_cast<size_t>(y) * w + x], inside ? 255 : 0) << x << "," << y;
    }
  }
  // at the image border the disc is cut off, not wrapped around
  const image::Gray8Image corner = RobotMask(OnePixel(6, 6, 0, 0), 2);
  EXPECT_EQ(corner.values[0 * 6 + 2], 255);
  EXPECT_EQ(corner.values[1 * 6 + 1], 255);
  EXPECT_EQ(corner.values[2 * 6 + 2], 0);
  EXPECT_EQ(corner.values[0 * 6 + 5], 0);
}

TEST(Underlay, ShowsTheImageAndTheRobotOverItAtAlpha) {
  image::Image colour{2, 1, {200, 100, 0, 10, 20, 30}};
  const image::Image underlay{2, 1, {0, 50, 255, 1, 2, 3}};
  const image::LabelImage robot{2, 1, {4, 0}};
  DrawUnderlay(underlay, "cam.png", 0.5, robot, colour);
  EXPECT_EQ(colour.rgb, (std::vector<std::uint8_t>{100, 75, 128, 1, 2, 3}));
  image::Image small{1, 1, {0, 0, 0}};
  EXPECT_EQ(test::ErrorText([&] { DrawUnderlay(small, "cam.png", 0.5, robot, colour); }),
            "cam.png: the underlay image is 1x1, the camera's image 2x1");
}

TEST(Underlay, EveryPixelDrawnOnIsShownOverTheImage) {
  // a robot pixel, a display's (red), the background (48 grey) and a robot pixel of that grey
  const image::Frame drawn{{4, 1, {90, 90, 90, 255, 0, 0, 48, 48, 48, 48, 48, 48}}, {}, {4, 1, {2, 0, 0, 7}}};
  const image::LabelImage pixels = DrawnPixels(drawn, Eigen::Vector3f(48 / 255.f, 48 / 255.f, 48 / 255.f));
  ASSERT_EQ(pixels.labels.size(), 4u);
  EXPECT_EQ(pixels.labels[0], 2);
  EXPECT_NE(pixels.labels[1], 0);
  EXPECT_EQ(pixels.labels[2], 0);
  EXPECT_EQ(pixels.labels[3], 7);
  image::Image colour = drawn.colour;
  DrawUnderlay(image::Image{4, 1, std::vector<std::uint8_t>(12, 200)}, "cam.png", 0.5, pixels, colour);
  EXPECT_EQ(colour.rgb, (std::vector<std::uint8_t>{145, 145, 145, 228, 100, 100, 200, 200, 200, 124, 124, 124}));
}

}  // namespace
}  // namespace urdfsnap::camera
