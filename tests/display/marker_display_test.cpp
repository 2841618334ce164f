// Markers kept as RViz's MarkerDisplay keeps them: by namespace and id, through ADD, DELETE and
// DELETEALL, until their lifetime ends; shown per namespace; placed by TF at their stamp unless
// frame_locked.
#include "display/marker_display.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace urdfsnap::display {
namespace {

using ::testing::HasSubstr;

constexpr std::int64_t kSecond = 1'000'000'000;

Marker Cube(const std::string& ns, int id, int action = Marker::kAdd) {
  Marker m;
  m.header.frame_id = "base";
  m.header.stamp_ns = kSecond;
  m.ns = ns;
  m.id = id;
  m.type = Marker::kCube;
  m.action = action;
  return m;
}

// "base" moves along x at 1 m/s in the fixed frame.
std::optional<Eigen::Isometry3d> Moving(const std::string& frame, std::int64_t t) {
  if (frame != "base") return std::nullopt;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation().x() = static_cast<double>(t) / kSecond;
  return X;
}

scene::Scene DrawAt(const MarkerDisplay& display, std::int64_t t, Warnings& warnings) {
  scene::Scene scene;
  display.Draw(t, Moving, scene, warnings);
  return scene;
}

TEST(MarkerDisplayTest, AddModifyDeleteAndDeleteAllByNamespaceAndId) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  display.Apply(Cube("a", 1), kSecond, "w", warnings);
  display.Apply(Cube("a", 2), kSecond, "w", warnings);
  display.Apply(Cube("b", 1), kSecond, "w", warnings);
  EXPECT_EQ(display.size(), 3u);
  Marker bigger = Cube("a", 1);
  bigger.scale = {2, 2, 2};
  display.Apply(bigger, kSecond, "w", warnings);   // replaces a/1
  EXPECT_EQ(display.size(), 3u);
  display.Apply(Cube("a", 2, Marker::kDelete), kSecond, "w", warnings);
  EXPECT_EQ(display.size(), 2u);
  const scene::Scene scene = DrawAt(display, kSecond, warnings);
  ASSERT_EQ(scene.items.size(), 2u);
  EXPECT_DOUBLE_EQ(scene.items[0].X_FG.linear()(0, 0), 2);
  display.Apply(Cube("", 0, Marker::kDeleteAll), kSecond, "w", warnings);
  EXPECT_EQ(display.size(), 0u);
  EXPECT_TRUE(warnings.empty());
}

TEST(MarkerDisplayTest, LifetimeCountsFromReceptionAndZeroIsForever) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  Marker brief = Cube("a", 1);
  brief.lifetime_ns = kSecond / 2;
  display.Apply(brief, kSecond, "w", warnings);
  display.Apply(Cube("a", 2), kSecond, "w", warnings);
  EXPECT_EQ(DrawAt(display, kSecond + kSecond / 4, warnings).items.size(), 2u);
  EXPECT_EQ(DrawAt(display, 2 * kSecond, warnings).items.size(), 1u);
}

TEST(MarkerDisplayTest, ExpiredMarkersAreDroppedNotJustHidden) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  for (int id = 0; id < 100; ++id) {   // a trail: a new id every 0.1 s, each living 0.25 s
    Marker brief = Cube("trail", id);
    brief.lifetime_ns = kSecond / 4;
    display.Expire(id * kSecond / 10);
    display.Apply(brief, id * kSecond / 10, "w", warnings);
  }
  EXPECT_EQ(display.size(), 3u);   // received at 9.7, 9.8 and 9.9 s
  display.Expire(20 * kSecond);
  EXPECT_EQ(display.size(), 0u);
}

TEST(MarkerDisplayTest, DisabledNamespacesAreNotDrawn) {
  MarkerSettings settings;
  settings.namespaces = {{"hidden", false}, {"shown", true}};
  MarkerDisplay display("/m", settings, {});
  Warnings warnings;
  for (const char* ns : {"hidden", "shown", "unlisted"}) display.Apply(Cube(ns, 0), kSecond, "w", warnings);
  EXPECT_EQ(DrawAt(display, kSecond, warnings).items.size(), 2u);
}

TEST(MarkerDisplayTest, FrameLockedMarkersFollowTheirFrameOthersStayAtTheirStamp) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  Marker locked = Cube("a", 1);
  locked.frame_locked = true;
  display.Apply(Cube("a", 0), kSecond, "w", warnings);
  display.Apply(locked, kSecond, "w", warnings);
  const scene::Scene scene = DrawAt(display, 3 * kSecond, warnings);
  ASSERT_EQ(scene.items.size(), 2u);
  EXPECT_DOUBLE_EQ(scene.items[0].X_FG.translation().x(), 1);
  EXPECT_DOUBLE_EQ(scene.items[1].X_FG.translation().x(), 3);
}

TEST(MarkerDisplayTest, BrokenMarkersAndUnknownFramesAreWarningsNamingTheMessage) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  Marker nan = Cube("a", 1);
  nan.scale.x() = std::nan("");
  display.Apply(nan, kSecond, "run.mcap: message 4 on '/m'", warnings);
  ASSERT_EQ(warnings.messages().size(), 1u);
  EXPECT_THAT(warnings.messages()[0], HasSubstr("run.mcap: message 4 on '/m': marker 'a/1'"));
  EXPECT_THAT(warnings.messages()[0], HasSubstr("nans or infs"));
  EXPECT_EQ(display.size(), 0u);

  Marker elsewhere = Cube("a", 2);
  elsewhere.header.frame_id = "nowhere";
  display.Apply(elsewhere, kSecond, "m5", warnings);
  EXPECT_TRUE(DrawAt(display, kSecond, warnings).items.empty());
  EXPECT_THAT(warnings.messages().back(), HasSubstr("m5: marker 'a/2': no transform from frame 'nowhere'"));
}

// A text marker's glyphs are rasterised once while it is drawn frame after frame: the display keeps
// the last frame's atlases, so the next frame's label shows the same texture (which the renderer
// then uploads once).
TEST(MarkerDisplayTest, TextKeepsItsGlyphTextureFromFrameToFrame) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  Marker text = Cube("t", 1);
  text.type = Marker::kTextViewFacing;
  text.text = "kept";
  display.Apply(text, kSecond, "w", warnings);
  const std::weak_ptr<const texture::TextureImage> first = DrawAt(display, kSecond, warnings).labels.at(0).texture;
  ASSERT_FALSE(first.expired());   // the frame's scene is gone; the display still holds its texture
  EXPECT_EQ(DrawAt(display, kSecond, warnings).labels.at(0).texture, first.lock());
  EXPECT_TRUE(warnings.empty());
}

// A TRIANGLE_LIST without colours is a lit mesh made when the marker arrives, not per frame: frame
// after frame it is the same mesh (so the renderer's GPU copy is made once), and a new message for
// the marker makes a new one.
TEST(MarkerDisplayTest, LitTriangleListKeepsItsMeshUntilTheMarkerChanges) {
  MarkerDisplay display("/m", {}, {});
  Warnings warnings;
  Marker triangles = Cube("t", 1);
  triangles.type = Marker::kTriangleList;
  triangles.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  display.Apply(triangles, kSecond, "w", warnings);
  const auto first = DrawAt(display, kSecond, warnings).items.at(0).mesh;
  EXPECT_EQ(DrawAt(display, 2 * kSecond, warnings).items.at(0).mesh, first);
  EXPECT_EQ(first->indices.size(), 6u);   // the triangle once per winding
  triangles.points[2].y() = 2;
  display.Apply(triangles, kSecond, "w", warnings);
  const auto second = DrawAt(display, kSecond, warnings).items.at(0).mesh;
  EXPECT_NE(second, first);
  EXPECT_FLOAT_EQ(second->positions.at(2).y(), 2);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace urdfsnap::display
