// The TF picture's names laid out (unit, no GL): scaled to a height in pixels, moved beside their
// frame when another name is in the way, left out when no place is free and then named in the
// page's note with the name drawn nearest.
#include <gtest/gtest.h>

#include "docs/tf_name_layout.h"

namespace urdfsnap::docs {
namespace {

// A name as the TF display lays it out: `characters` cells of 0.1 m, centred and hanging below.
scene::TextLabel Name(int characters, const Eigen::Vector3d& anchor) {
  scene::TextLabel label;
  for (int c = 0; c < characters; ++c) {
    const float left = -0.05f * characters + 0.1f * c;
    label.quads.push_back({{left, -0.1f}, {left + 0.1f, 0}, {0, 1}, {1, 0}});
  }
  label.anchor = anchor;
  return label;
}

// Looking down -X at the origin from 5 m: a frame at (0, y, z) is y m left and z m up.
scene::OrbitView FrontView() {
  scene::OrbitView view;
  view.yaw = 0;
  view.pitch = 0;
  view.distance = 5;
  return view;
}

struct Extent {
  float width, height;
};
Extent ExtentOf(const scene::TextLabel& label) {
  Eigen::Vector2f low = label.quads.front().min, high = label.quads.front().max;
  for (const auto& quad : label.quads) {
    low = low.cwiseMin(quad.min);
    high = high.cwiseMax(quad.max);
  }
  return {high.x() - low.x(), high.y() - low.y()};
}

TEST(TfNameLayout, ScalesNamesToTheirHeightInPixels) {
  scene::Scene scene;
  scene.labels = {Name(4, {0, 0, 0})};
  const render::ImageSize size{640, 480};
  const scene::OrbitView view = FrontView();
  EXPECT_TRUE(LayOutTfNames(scene, {"base"}, view, size, 13).empty());
  ASSERT_EQ(scene.labels.size(), 1u);
  // brought a quarter of the way to the eye at (5, 0, 0), where it covers the same pixels
  EXPECT_TRUE(scene.labels[0].anchor.isApprox(Eigen::Vector3d(1.25, 0, 0))) << scene.labels[0].anchor.transpose();
  const double metres_per_pixel = 3.75 * 2 * std::tan(view.fov_y / 2) / size.height;
  EXPECT_NEAR(ExtentOf(scene.labels[0]).height / metres_per_pixel, 13, 1e-3);
  EXPECT_NEAR(ExtentOf(scene.labels[0]).width / metres_per_pixel, 4 * 13, 1e-3);   // square cells, as given
  // hung below its frame: the top edge under the origin
  for (const auto& quad : scene.labels[0].quads) EXPECT_LE(quad.max.y(), 0);
}

TEST(TfNameLayout, MovesANameInTheWayAndLeavesOutOneWithNoPlace) {
  scene::Scene scene;
  // five frames at one point (a hand, its flange, tool point ...), one far away
  scene.labels = {Name(5, {0, 0, 0}), Name(5, {0, 0, 0}), Name(5, {0, 0, 0}), Name(5, {0, 0, 0}),
                  Name(5, {0, 0, 0}), Name(3, {0, 1.5, 1})};
  const std::vector<std::string> frames = {"hand", "flange", "tcp", "tool0", "wrist", "far"};
  const std::vector<LeftOutName> left_out = LayOutTfNames(scene, frames, FrontView(), {640, 480}, 13);
  // the rows below, above, second below and second above hold four; the fifth has no place
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_EQ(left_out[0].frame, "wrist");
  EXPECT_EQ(left_out[0].near, "hand");
  EXPECT_EQ(scene.labels.size(), 5u);
  EXPECT_EQ(LeftOutNote(left_out),
            "The TF picture leaves out 1 frame name that would overlap others; each is listed by the name drawn "
            "nearest it: wrist near hand.");
  EXPECT_EQ(LeftOutNote({}), "");
}

TEST(TfNameLayout, NamesBehindTheCameraAreNotDrawnNorListed) {
  scene::Scene scene;
  scene.labels = {Name(3, {10, 0, 0})};   // behind the eye at x = 5
  EXPECT_TRUE(LayOutTfNames(scene, {"behind"}, FrontView(), {640, 480}).empty());
  EXPECT_TRUE(scene.labels.empty());
}

}  // namespace
}  // namespace urdfsnap::docs
