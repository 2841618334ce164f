// The point-cloud displays' properties from a .rviz display section: every property away from its
// default as RViz 1.14 saves it (Min/Max Value under Autocompute Value Bounds), RViz's defaults for
// missing keys and its limits, and errors at the line of a bad value (unit).
#include "request/internal/rviz_point_clouds.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "request/internal/rviz_properties.h"

namespace urdfsnap::request {
namespace {

using ::testing::HasSubstr;
using Colour = display::PointCloudSettings::Colour;

display::PointCloudSettings Read(const std::string& text, Warnings& warnings) {
  const YAML::Node node = LoadYaml(text, "view.rviz");
  return ReadPointCloudSettings(RvizSection("view.rviz", node, "PointCloud2 display 'cloud'"), warnings);
}

TEST(RvizPointCloudsTest, ReadsEveryPropertyAsRVizSavesIt) {
  Warnings warnings;
  const display::PointCloudSettings s = Read(R"(Alpha: 0.5
Autocompute Intensity Bounds: false
Autocompute Value Bounds:
  Max Value: 3
  Min Value: -1
  Value: false
Axis: X
Channel Name: strength
Class: rviz/PointCloud2
Color: 10; 20; 30
Color Transformer: AxisColor
Decay Time: 2
Enabled: true
Invert Rainbow: true
Max Color: 255; 0; 0
Max Intensity: 100
Min Color: 0; 0; 255
Min Intensity: 5
Name: cloud
Position Transformer: XYZ
Queue Size: 10
Selectable: true
Size (Pixels): 4
Size (m): 0.05
Style: Boxes
Topic: /points
Unreliable: false
Use Fixed Frame: false
Use rainbow: false
Value: true
)", warnings);
  EXPECT_EQ(s.style, scene::PointSet::Style::kBoxes);
  EXPECT_FLOAT_EQ(s.size_m, 0.05f);
  EXPECT_FLOAT_EQ(s.size_px, 4);
  EXPECT_FLOAT_EQ(s.alpha, 0.5f);
  EXPECT_EQ(s.decay_time, 2);
  EXPECT_EQ(s.colour, Colour::kAxisColor);
  EXPECT_EQ(s.channel, "strength");
  EXPECT_FALSE(s.use_rainbow);
  EXPECT_TRUE(s.invert_rainbow);
  EXPECT_TRUE(s.min_colour.isApprox(Eigen::Vector3f(0, 0, 1)));
  EXPECT_TRUE(s.max_colour.isApprox(Eigen::Vector3f(1, 0, 0)));
  EXPECT_FALSE(s.auto_intensity_bounds);
  EXPECT_FLOAT_EQ(s.min_intensity, 5);
  EXPECT_FLOAT_EQ(s.max_intensity, 100);
  EXPECT_EQ(s.axis, 0);
  EXPECT_FALSE(s.auto_axis_bounds);
  EXPECT_FLOAT_EQ(s.min_value, -1);
  EXPECT_FLOAT_EQ(s.max_value, 3);
  EXPECT_FALSE(s.axis_in_fixed_frame);
  EXPECT_TRUE(s.flat_colour.isApprox(Eigen::Vector3f(10, 20, 30) / 255.f));
  EXPECT_TRUE(warnings.empty());
}

TEST(RvizPointCloudsTest, MissingKeysKeepRVizDefaultsAndValuesAreLimited) {
  Warnings warnings;
  EXPECT_EQ(Read("Class: rviz/LaserScan\n", warnings), display::PointCloudSettings{});
  const display::PointCloudSettings limited = Read("Alpha: 3\nSize (m): 0\nSize (Pixels): 0\n", warnings);
  EXPECT_EQ(limited.alpha, 1);
  EXPECT_FLOAT_EQ(limited.size_m, 0.0001f);
  EXPECT_EQ(limited.size_px, 1);
  EXPECT_EQ(Read("Color Transformer: \"\"\n", warnings).colour, Colour::kAuto);
}

TEST(RvizPointCloudsTest, BadValuesAreErrorsAtTheirLine) {
  Warnings warnings;
  const auto error = [&](const std::string& text) {
    try {
      Read(text, warnings);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(error("Alpha: 1\nStyle: Circles\n"),
              HasSubstr("view.rviz:2: PointCloud2 display 'cloud': 'Style': expected one of Points, Squares, "
                        "Flat Squares, Spheres, Boxes, got 'Circles'"));
  EXPECT_THAT(error("Color Transformer: Rainbow\n"), HasSubstr("view.rviz:1:"));
  EXPECT_THAT(error("Min Color: red\n"), HasSubstr("'Min Color': expected a colour"));
  Read("Position Transformer: Custom\n", warnings);
  ASSERT_EQ(warnings.messages().size(), 1u);
  EXPECT_THAT(warnings.messages()[0], HasSubstr("Position Transformer"));
}

}  // namespace
}  // namespace urdfsnap::request
