// Path, PoseArray and Axes displays: their shapes with RViz's defaults and settings.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "display/axes_display.h"
#include "display/make_display.h"
#include "display/path_display.h"
#include "display/pose_array_display.h"

namespace urdfsnap::display {
namespace {

using ::testing::HasSubstr;

std::optional<Eigen::Isometry3d> Shifted(const std::string& frame, std::int64_t) {
  if (frame != "map" && frame != "odom") return std::nullopt;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation().z() = frame == "map" ? 1 : 2;
  return X;
}

PoseList Poses(int n) {
  PoseList list{{"map", 0}, {}};
  for (int i = 0; i < n; ++i) list.poses.push_back({Eigen::Vector3d(i, 0, 0), Eigen::Quaterniond::Identity()});
  return list;
}

scene::Scene DrawAt(const Display& display, Warnings& warnings) {
  scene::Scene scene;
  display.Draw(0, Shifted, scene, warnings);
  return scene;
}

TEST(PathDisplayTest, LinesThroughThePosesInThePathsColour) {
  PathDisplay display("/path", {});
  Warnings warnings;
  display.Keep(Poses(3), 0, "w", warnings);
  const scene::Scene scene = DrawAt(display, warnings);
  ASSERT_EQ(scene.lines.size(), 1u);
  EXPECT_EQ(scene.lines[0].width, 0);   // 1-pixel lines
  EXPECT_TRUE(scene.lines[0].rgba.isApprox(Eigen::Vector4f(25 / 255.f, 1, 0, 1)));
  ASSERT_EQ(scene.lines[0].points.size(), 4u);
  EXPECT_EQ(scene.lines[0].points[3], Eigen::Vector3f(2, 0, 1));
}

TEST(PathDisplayTest, BillboardsBufferAndOffset) {
  PathSettings settings;
  settings.line_style = PathSettings::LineStyle::kBillboards;
  settings.buffer_length = 2;
  settings.offset = {0, 1, 0};
  PathDisplay display("/path", settings);
  Warnings warnings;
  for (int i = 0; i < 3; ++i) display.Keep(Poses(2), 0, "w", warnings);
  const scene::Scene scene = DrawAt(display, warnings);
  ASSERT_EQ(scene.lines.size(), 2u);
  EXPECT_FLOAT_EQ(scene.lines[0].width, 0.03f);
  EXPECT_EQ(scene.lines[0].points[0], Eigen::Vector3f(0, 1, 1));
}

TEST(PoseArrayDisplayTest, FlatArrowsAreAShaftAndTwoBarbs) {
  PoseArrayDisplay display("/poses", {});
  Warnings warnings;
  PoseList list = Poses(1);
  list.poses[0].orientation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  display.Keep(list, 0, "w", warnings);
  const scene::Scene scene = DrawAt(display, warnings);
  ASSERT_EQ(scene.lines.size(), 1u);
  const auto& p = scene.lines[0].points;
  ASSERT_EQ(p.size(), 6u);
  EXPECT_TRUE(p[1].isApprox(Eigen::Vector3f(0, 0.3f, 1)));                 // the tip
  EXPECT_TRUE(p[2].isApprox(Eigen::Vector3f(-0.06f, 0.225f, 1)));          // a barb's end
  EXPECT_TRUE(scene.lines[0].rgba.isApprox(Eigen::Vector4f(1, 25 / 255.f, 0, 1)));
}

TEST(PoseArrayDisplayTest, Arrow3dAndAxesShapes) {
  PoseArraySettings settings;
  settings.shape = PoseArraySettings::Shape::kArrow3d;
  PoseArrayDisplay arrows("/poses", settings);
  settings.shape = PoseArraySettings::Shape::kAxes;
  PoseArrayDisplay axes("/poses", settings);
  Warnings warnings;
  arrows.Keep(Poses(2), 0, "w", warnings);
  axes.Keep(Poses(2), 0, "w", warnings);
  const scene::Scene a = DrawAt(arrows, warnings);
  ASSERT_EQ(a.items.size(), 4u);   // shaft and head per pose
  EXPECT_TRUE(a.items[0].X_FG.translation().isApprox(Eigen::Vector3d(0.115, 0, 1)));
  EXPECT_TRUE(DrawAt(axes, warnings).lines.empty());
  EXPECT_EQ(DrawAt(axes, warnings).items.size(), 6u);
}

TEST(PoseArrayDisplayTest, NonFinitePosesAreAWarningAndNotKept) {
  PoseArrayDisplay display("/poses", {});
  Warnings warnings;
  PoseList list = Poses(2);
  list.poses[1].orientation.x() = std::nan("");
  display.Keep(list, 0, "bag: message 2 on '/poses'", warnings);
  EXPECT_THAT(warnings.messages().at(0), HasSubstr("bag: message 2 on '/poses': message contains invalid"));
  EXPECT_TRUE(DrawAt(display, warnings).lines.empty());
}

TEST(AxesDisplayTest, AxesAtTheReferenceFrameOrTheFixedFrame) {
  Warnings warnings;
  const auto fixed = MakeDisplay({"Axes", "", AxesSettings{}}, "map", {});
  scene::Scene scene = DrawAt(*fixed, warnings);
  ASSERT_EQ(scene.items.size(), 3u);
  EXPECT_TRUE(scene.items[0].X_FG.translation().isApprox(Eigen::Vector3d(0.5, 0, 1)));
  EXPECT_TRUE(scene.items[0].rgba.isApprox(Eigen::Vector4f(1, 0, 0, 1)));
  EXPECT_TRUE(scene.items[2].X_FG.translation().isApprox(Eigen::Vector3d(0, 0, 1.5)));
  EXPECT_NEAR(scene.items[2].X_FG.linear().col(0).norm(), 0.1, 1e-9);   // Radius is a diameter
  AxesSettings other;
  other.reference_frame = "lost";
  scene = {};
  MakeDisplay({"Axes", "", other}, "map", {})->Draw(0, Shifted, scene, warnings);
  EXPECT_TRUE(scene.items.empty());
  EXPECT_THAT(warnings.messages().back(), HasSubstr("no transform from frame 'lost'"));
}

}  // namespace
}  // namespace urdfsnap::display
