// The message displays of .rviz files: RViz 1 (as the display reference scenes save them) and
// RViz 2 property names, defaults, namespaces, and bad values.
#include "request/internal/rviz_displays.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "request/rviz_config.h"
#include "support/error_text.h"

namespace urdfsnap::request {
namespace {

using ::testing::HasSubstr;

std::vector<display::DisplaySettings> Displays(const std::string& displays, Warnings& warnings) {
  return ParseRvizConfig("Visualization Manager:\n  Displays:\n" + displays, "v.rviz", {}, warnings).displays;
}

TEST(RvizDisplaysTest, Rviz1DisplaysWithTheirProperties) {
  Warnings warnings;
  const auto displays = Displays(R"(    - Class: rviz/MarkerArray
      Enabled: true
      Marker Topic: /markers
      Name: MarkerArray
      Namespaces:
        scene: true
        hidden: false
      Queue Size: 100
      Value: true
    - Class: rviz/Path
      Alpha: 0.5
      Buffer Length: 3
      Color: 255; 0; 0
      Enabled: true
      Line Style: Billboards
      Line Width: 0.1
      Name: Path
      Offset:
        X: 1
        Y: 0
        Z: 0
      Pose Style: None
      Topic: /path
    - Class: rviz/PoseArray
      Enabled: true
      Name: PoseArray
      Shape: Arrow (3D)
      Shaft Length: 0.5
      Topic: /poses
    - Class: rviz/Axes
      Enabled: true
      Length: 2
      Name: Axes
      Radius: 0.2
      Reference Frame: /tool
    - Class: rviz/Marker
      Enabled: false
      Name: Off
)", warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(displays.size(), 4u);   // the disabled Marker display is left out
  EXPECT_EQ(displays[0].topic, "/markers");
  const auto& markers = std::get<display::MarkerSettings>(displays[0].kind);
  EXPECT_TRUE(markers.array);
  EXPECT_EQ(markers.namespaces, (std::map<std::string, bool>{{"hidden", false}, {"scene", true}}));
  const auto& path = std::get<display::PathSettings>(displays[1].kind);
  EXPECT_EQ(displays[1].topic, "/path");
  EXPECT_EQ(path.line_style, display::PathSettings::LineStyle::kBillboards);
  EXPECT_EQ(path.colour, Eigen::Vector3f(1, 0, 0));
  EXPECT_EQ(path.alpha, 0.5f);
  EXPECT_EQ(path.line_width, 0.1);
  EXPECT_EQ(path.buffer_length, 3);
  EXPECT_EQ(path.offset, Eigen::Vector3d(1, 0, 0));
  const auto& poses = std::get<display::PoseArraySettings>(displays[2].kind);
  EXPECT_EQ(poses.shape, display::PoseArraySettings::Shape::kArrow3d);
  EXPECT_EQ(poses.shaft_length, 0.5);
  EXPECT_EQ(poses.head_length, 0.07);   // RViz's default
  const auto& axes = std::get<display::AxesSettings>(displays[3].kind);
  EXPECT_EQ(axes.reference_frame, "tool");
  EXPECT_EQ(axes.length, 2);
  EXPECT_EQ(axes.radius, 0.2);
}

TEST(RvizDisplaysTest, Rviz2NamesAndDefaults) {
  Warnings warnings;
  const auto displays = Displays(R"(    - Class: rviz_default_plugins/Marker
      Enabled: true
      Name: Marker
      Topic:
        Depth: 5
        Value: /goal_marker
    - Class: rviz_default_plugins/PoseArray
      Arrow 2D Length: 0.5
      Enabled: true
      Name: PoseArray
      Topic:
        Value: /particles
    - Class: rviz_default_plugins/Path
      Enabled: true
      Name: Path
)", warnings);
  ASSERT_EQ(displays.size(), 3u);
  EXPECT_EQ(displays[0].topic, "/goal_marker");
  EXPECT_FALSE(std::get<display::MarkerSettings>(displays[0].kind).array);
  EXPECT_EQ(std::get<display::PoseArraySettings>(displays[1].kind).arrow_length, 0.5);
  EXPECT_EQ(displays[1].topic, "/particles");
  EXPECT_EQ(std::get<display::PathSettings>(displays[2].kind), display::PathSettings{});
}

TEST(RvizDisplaysTest, BadValuesAreErrorsAtTheirLineAndUnfollowedOnesWarnings) {
  Warnings warnings;
  EXPECT_THAT(test::ErrorText([&] {
                Displays("    - Class: rviz/PoseArray\n      Enabled: true\n      Shape: Star\n", warnings);
              }),
              HasSubstr("v.rviz:5: "));
  Displays("    - Class: rviz/Path\n      Enabled: true\n      Name: P\n      Pose Style: Axes\n", warnings);
  EXPECT_THAT(warnings.messages().at(0), HasSubstr("v.rviz:6: rviz/Path display 'P': 'Pose Style' is not None"));
}

}  // namespace
}  // namespace urdfsnap::request
