// The remap from a pinhole render to a distorted camera image: each raw pixel shows what lies on
// its ray, depth and labels are copied from one pinhole pixel, pixels without a ray are empty.
#include <gtest/gtest.h>

#include <cmath>

#include "camera/distortion_remap.h"
#include "support/error_text.h"

namespace urdfsnap::camera {
namespace {

// a pinhole "render" of a scene whose values are functions of the ray: colour red = 100 + 50·x/z,
// label 1 left of the optical axis and 2 right of it, depth 2 + y/z
image::Frame RenderRays(const PinholeImage& pinhole) {
  const int w = pinhole.width, h = pinhole.height;
  image::Frame frame;
  frame.colour = {w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 3, 0)};
  frame.depth = {w, h, std::vector<float>(static_cast<size_t>(w) * h)};
  frame.labels = {w, h, std::vector<std::uint16_t>(static_cast<size_t>(w) * h)};
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const Eigen::Vector2d ray = FromPixel(pinhole.k, {u, v});
      const size_t i = static_cast<size_t>(v) * w + u;
      frame.colour.rgb[i * 3] = static_cast<std::uint8_t>(std::lround(std::clamp(100 + 50 * ray.x(), 0.0, 255.0)));
      frame.labels.labels[i] = ray.x() < 0 ? 1 : 2;
      frame.depth.metres[i] = static_cast<float>(2 + ray.y());
    }
  }
  return frame;
}

TEST(DistortionRemap, EachRawPixelShowsItsRay) {
  const PinholeImage raw{{200, 190, 81.5, 58.25}, 160, 120};
  std::string why;
  const Distortion d = *MakeDistortion("plumb_bob", {-0.3, 0.1, 0.001, -0.002, 0}, why);
  const DistortionRemap remap(raw, d);
  const image::Frame out = remap.Apply(RenderRays(remap.source()));
  ASSERT_EQ(out.colour.width, 160);
  ASSERT_EQ(out.labels.height, 120);
  for (int v = 0; v < raw.height; v += 7) {
    for (int u = 0; u < raw.width; u += 5) {
      const std::optional<Eigen::Vector2d> ray = Undistort(d, FromPixel(raw.k, {u, v}));
      ASSERT_TRUE(ray);
      const size_t i = static_cast<size_t>(v) * raw.width + u;
      // colour is interpolated: within one step of the source's rounding
      EXPECT_NEAR(out.colour.rgb[i * 3], 100 + 50 * ray->x(), 1.0) << u << "," << v;
      // depth and label come from the nearest pinhole pixel: within half a pinhole pixel's ray
      EXPECT_NEAR(out.depth.metres[i], 2 + ray->y(), 0.5 / remap.source().k.fy + 1e-6);
      if (std::abs(ray->x()) > 1.0 / remap.source().k.fx) {
        EXPECT_EQ(out.labels.labels[i], ray->x() < 0 ? 1 : 2);
      }
    }
  }
}

TEST(DistortionRemap, PixelsWithoutARayAreEmpty) {
  // so strong a barrel lens that the corners have no ray
  const PinholeImage raw{{40, 40, 39.5, 29.5}, 80, 60};
  std::string why;
  const DistortionRemap remap(raw, *MakeDistortion("plumb_bob", {-0.9, 0, 0, 0, 0}, why));
  const image::Frame out = remap.Apply(RenderRays(remap.source()));
  EXPECT_EQ(out.labels.labels[0], 0);
  EXPECT_TRUE(std::isnan(out.depth.metres[0]));
  EXPECT_EQ(out.colour.rgb[0], 0);
  EXPECT_NE(out.labels.labels[30 * 80 + 40], 0);
  EXPECT_LE(remap.source().width, 3 * 80);
}

TEST(DistortionRemap, OnlyThePresentImagesAreRemappedAndSizesAreChecked) {
  const PinholeImage raw{{50, 50, 9.5, 9.5}, 20, 20};
  std::string why;
  const DistortionRemap remap(raw, *MakeDistortion("plumb_bob", {0.1, 0, 0, 0, 0}, why));
  image::Frame labels_only;
  labels_only.labels = RenderRays(remap.source()).labels;
  const image::Frame out = remap.Apply(labels_only);
  EXPECT_TRUE(out.colour.rgb.empty());
  EXPECT_TRUE(out.depth.metres.empty());
  EXPECT_EQ(out.labels.labels.size(), 400u);
  image::Frame wrong;
  wrong.colour = {3, 3, std::vector<std::uint8_t>(27)};
  EXPECT_EQ(test::ErrorText([&] { remap.Apply(wrong); }),
            "DistortionRemap: the colour image is 3x3, the pinhole render " +
                image::SizeText(remap.source().width, remap.source().height));
}

}  // namespace
}  // namespace urdfsnap::camera
