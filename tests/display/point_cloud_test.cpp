// PointCloud2 and LaserScan without GL: RViz's NaN filter, each colour transformer with its
// rules (RGB8 bits, rgba alpha, the Intensity rainbow and its bounds, min/max colours, AxisColor,
// FlatColor, the automatic choice), byte order, padded rows, laser projection, and clouds whose
// claims do not fit their bytes.
#include "display/point_cloud.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "display/laser_scan.h"
#include "display/point_cloud_colours.h"
#include "display/point_cloud_reader.h"
#include "support/error_text.h"

namespace urdfsnap::display {
namespace {

using ::testing::HasSubstr;
using Colour = PointCloudSettings::Colour;
constexpr std::uint8_t kFloat32 = 7, kUint8 = 2, kUint32 = 6, kFloat64 = 8;

// A one-row cloud of float32 fields `names`, each point's values given in order.
PointCloud2 FloatCloud(const std::vector<std::string>& names, const std::vector<std::vector<float>>& points) {
  PointCloud2 cloud;
  cloud.frame_id = "lidar";
  for (std::size_t f = 0; f < names.size(); ++f) {
    cloud.fields.push_back({names[f], static_cast<std::uint32_t>(4 * f), kFloat32, 1});
  }
  cloud.point_step = static_cast<std::uint32_t>(4 * names.size());
  cloud.height = 1;
  cloud.width = static_cast<std::uint32_t>(points.size());
  cloud.row_step = cloud.width * cloud.point_step;
  for (const auto& point : points) {
    const std::size_t at = cloud.data.size();
    cloud.data.resize(at + cloud.point_step);
    std::memcpy(cloud.data.data() + at, point.data(), cloud.point_step);
  }
  return cloud;
}

float PackedRgb(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, 4);
  return value;
}

scene::PointSet Draw(const PointCloud2& cloud, const PointCloudSettings& settings = {},
                     const Eigen::Isometry3d& X_FC = Eigen::Isometry3d::Identity()) {
  return CloudPointSet(cloud, settings, X_FC);
}

TEST(PointCloudTest, Rgb8ReadsTheFloatsBitsAsRgbAndSkipsNaNPoints) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const PointCloud2 cloud = FloatCloud({"x", "y", "z", "rgb"}, {{1, 2, 3, PackedRgb(0x00FF8000)},
                                                               {nan, 0, 0, PackedRgb(0x000000FF)},
                                                               {4, 5, 6, PackedRgb(0xAA0000FF)}});
  const scene::PointSet points = Draw(cloud);
  ASSERT_EQ(points.positions.size(), 2u);
  EXPECT_EQ(points.positions[1], Eigen::Vector3f(4, 5, 6));
  EXPECT_TRUE(points.colours[0].isApprox(Eigen::Vector4f(1, 128 / 255.f, 0, 1)));
  // rgb ignores the top byte
  EXPECT_TRUE(points.colours[1].isApprox(Eigen::Vector4f(0, 0, 1, 1)));
  EXPECT_EQ(points.style, scene::PointSet::Style::kFlatSquares);
  EXPECT_EQ(points.size, Eigen::Vector3f::Constant(0.01f));
}

TEST(PointCloudTest, RgbaCarriesAlphaTimesTheDisplaysAlpha) {
  const PointCloud2 cloud = FloatCloud({"x", "y", "z", "rgba"}, {{0, 0, 0, PackedRgb(0x80FF0000)}});
  PointCloudSettings settings;
  settings.alpha = 0.5f;
  const scene::PointSet points = Draw(cloud, settings);
  EXPECT_TRUE(points.colours[0].isApprox(Eigen::Vector4f(1, 0, 0, 0.5f * 128 / 255.f)));
}

TEST(PointCloudTest, IntensityRainbowGoesFromRedAtTheMinimumToMagentaAtTheMaximum) {
  const PointCloud2 cloud = FloatCloud({"x", "y", "z", "intensity"}, {{0, 0, 0, 10}, {1, 0, 0, 30}, {2, 0, 0, 20}});
  const scene::PointSet points = Draw(cloud);   // no rgb field: Intensity, bounds from the cloud
  EXPECT_TRUE(points.colours[0].isApprox(Eigen::Vector4f(1, 0, 0, 1)));
  EXPECT_TRUE(points.colours[1].isApprox(Eigen::Vector4f(1, 0, 1, 1)));
  EXPECT_TRUE(points.colours[2].isApprox(Eigen::Vector4f(0, 1, 0.5f, 1)));   // halfway: green-cyan
  PointCloudSettings inverted;
  inverted.invert_rainbow = true;
  EXPECT_TRUE(Draw(cloud, inverted).colours[0].isApprox(Eigen::Vector4f(1, 0, 1, 1)));
  // given bounds: 10 is the middle of [0, 20]; values outside clamp
  PointCloudSettings given;
  given.auto_intensity_bounds = false;
  given.min_intensity = 0;
  given.max_intensity = 20;
  const scene::PointSet bounded = Draw(cloud, given);
  EXPECT_TRUE(bounded.colours[0].isApprox(Eigen::Vector4f(0, 1, 0.5f, 1)));
  EXPECT_TRUE(bounded.colours[1].isApprox(Eigen::Vector4f(1, 0, 1, 1)));
}

TEST(PointCloudTest, IntensityWithoutRainbowBlendsMinAndMaxColours) {
  const PointCloud2 cloud = FloatCloud({"x", "y", "z", "strength"}, {{0, 0, 0, 0}, {0, 0, 0, 4}, {0, 0, 0, 1}});
  PointCloudSettings settings;
  settings.colour = Colour::kIntensity;
  settings.channel = "strength";
  settings.use_rainbow = false;
  settings.min_colour = {0, 0, 1};
  settings.max_colour = {1, 1, 0};
  const scene::PointSet points = Draw(cloud, settings);
  EXPECT_TRUE(points.colours[0].isApprox(Eigen::Vector4f(0, 0, 1, 1)));
  EXPECT_TRUE(points.colours[1].isApprox(Eigen::Vector4f(1, 1, 0, 1)));
  EXPECT_TRUE(points.colours[2].isApprox(Eigen::Vector4f(0.25f, 0.25f, 0.75f, 1)));
}

TEST(PointCloudTest, IntensityWithoutItsChannelLeavesPointsWhite) {
  const scene::PointSet points = Draw(FloatCloud({"x", "y", "z"}, {{0, 0, 0}}));
  EXPECT_EQ(points.colours[0], Eigen::Vector4f::Ones());
}

TEST(PointCloudTest, AxisColorRunsTheRainbowAlongTheAxisInTheFixedFrame) {
  const PointCloud2 cloud = FloatCloud({"x", "y", "z", "rgb"}, {{0, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 2, 0}});
  PointCloudSettings settings;
  settings.colour = Colour::kAxisColor;
  // the cloud's z is the fixed frame's -x: along fixed Z every point has the same value
  Eigen::Isometry3d X_FC = Eigen::Isometry3d::Identity();
  X_FC.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  X_FC.translation() = Eigen::Vector3d(0, 0, 5);
  const scene::PointSet fixed = Draw(cloud, settings, X_FC);
  EXPECT_TRUE(fixed.positions[2].isApprox(Eigen::Vector3f(2, 0, 5)));
  EXPECT_TRUE(fixed.colours[0].isApprox(fixed.colours[2]));
  settings.axis_in_fixed_frame = false;
  const scene::PointSet local = Draw(cloud, settings, X_FC);
  EXPECT_TRUE(local.colours[0].isApprox(Eigen::Vector4f(1, 0, 0, 1)));   // lowest z: red
  EXPECT_TRUE(local.colours[2].isApprox(Eigen::Vector4f(1, 0, 1, 1)));   // highest: magenta
}

TEST(PointCloudTest, FlatColorAndPointsSize) {
  PointCloudSettings settings;
  settings.colour = Colour::kFlatColor;
  settings.flat_colour = {0.2f, 0.4f, 0.6f};
  settings.style = scene::PointSet::Style::kPoints;
  settings.size_px = 5;
  const scene::PointSet points = Draw(FloatCloud({"x", "y", "z", "rgb"}, {{0, 0, 0, 0}}), settings);
  EXPECT_TRUE(points.colours[0].isApprox(Eigen::Vector4f(0.2f, 0.4f, 0.6f, 1)));
  EXPECT_EQ(points.size, Eigen::Vector3f::Constant(5));
}

TEST(PointCloudTest, AskedTransformerTheCloudCannotUseFallsBackToRViz) {
  PointCloudSettings settings;
  settings.colour = Colour::kRgb8;
  const PointCloud2 cloud = FloatCloud({"x", "y", "z"}, {{0, 0, 0}});
  const PointCloudReader reader(cloud);
  EXPECT_EQ(ChooseColour(reader, settings), Colour::kIntensity);
}

TEST(PointCloudTest, ReadsBigEndianCloudsAndPaddedRows) {
  PointCloud2 cloud = FloatCloud({"x", "y", "z", "i"}, {{1.5f, -2, 3, 7}});
  for (std::size_t at = 0; at < cloud.data.size(); at += 4) std::reverse(&cloud.data[at], &cloud.data[at + 4]);
  cloud.is_bigendian = true;
  EXPECT_EQ(Draw(cloud).positions[0], Eigen::Vector3f(1.5f, -2, 3));
  // 2 x 2 organised cloud whose rows carry 8 bytes of padding
  PointCloud2 organised = FloatCloud({"x", "y", "z"}, {{1, 0, 0}, {2, 0, 0}});
  organised.height = 2;
  organised.width = 2;
  organised.row_step = 2 * 12 + 8;
  std::vector<std::uint8_t> data(organised.data);
  data.resize(32, 0xEE);
  const std::vector<std::uint8_t> second_row = FloatCloud({"x", "y", "z"}, {{3, 0, 0}, {4, 0, 0}}).data;
  data.insert(data.end(), second_row.begin(), second_row.end());
  organised.data = data;
  const scene::PointSet points = Draw(organised);
  ASSERT_EQ(points.positions.size(), 4u);
  EXPECT_EQ(points.positions[2].x(), 3);
  EXPECT_EQ(points.positions[3].x(), 4);
}

TEST(PointCloudTest, ValuesOfEveryDatatypeReadAsFloats) {
  PointCloud2 cloud = FloatCloud({"x", "y", "z"}, {{0, 0, 0}});
  cloud.fields.push_back({"u8", 12, kUint8, 1});
  cloud.fields.push_back({"u32", 16, kUint32, 1});
  cloud.fields.push_back({"f64", 20, kFloat64, 1});
  cloud.point_step = 28;
  cloud.data.resize(28);
  cloud.data[12] = 200;
  const std::uint32_t u32 = 70000;
  std::memcpy(&cloud.data[16], &u32, 4);
  const double f64 = -0.25;
  std::memcpy(&cloud.data[20], &f64, 8);
  const PointCloudReader reader(cloud);
  EXPECT_EQ(reader.Value(reader.Field("u8"), 0), 200);
  EXPECT_EQ(reader.Value(reader.Field("u32"), 0), 70000);
  EXPECT_EQ(reader.Value(reader.Field("f64"), 0), -0.25f);
}

struct LyingCloud {
  const char* name;
  void (*lie)(PointCloud2&);
  const char* error;
};

class LyingCloudTest : public ::testing::TestWithParam<LyingCloud> {};

// each claim that does not fit the bytes is a CloudError saying which, before any point is read
TEST_P(LyingCloudTest, IsAnErrorNamingTheClaim) {
  PointCloud2 cloud = FloatCloud({"x", "y", "z", "rgb"}, {{0, 0, 0, 0}, {1, 1, 1, 0}});
  GetParam().lie(cloud);
  EXPECT_THAT(test::ErrorText<CloudError>([&] { Draw(cloud); }), HasSubstr(GetParam().error));
}

INSTANTIATE_TEST_SUITE_P(
    Hostile, LyingCloudTest,
    ::testing::Values(
        LyingCloud{"data_shorter_than_claimed", [](PointCloud2& c) { c.data.resize(20); },
                   "data holds 20 bytes, fewer than the 32"},
        LyingCloud{"hundred_million_points", [](PointCloud2& c) { c.width = 100'000'000; },
                   "fewer than the 1600000000"},
        LyingCloud{"huge_rows", [](PointCloud2& c) { c.height = 4'294'967'295u; c.width = 1; c.row_step = 4'294'967'295u; },
                   "data holds 32 bytes"},
        LyingCloud{"huge_row_and_step",
                   [](PointCloud2& c) { c.height = 4'294'967'295u; c.width = 4'294'967'295u; c.point_step = 4'294'967'295u; c.row_step = 4'294'967'295u; },
                   "row_step 4294967295 is less than width"},
        LyingCloud{"huge_single_row", [](PointCloud2& c) { c.width = 4'294'967'295u; c.point_step = 4'294'967'295u; },
                   "data holds 32 bytes"},
        LyingCloud{"rows_overlap", [](PointCloud2& c) { c.width = 1; c.height = 2; c.row_step = 4; },
                   "row_step 4 is less than width (1) times point_step (16)"},
        LyingCloud{"offset_past_point_step", [](PointCloud2& c) { c.fields[2].offset = 14; },
                   "field 'z' (4 bytes at offset 14) does not fit in point_step 16"},
        LyingCloud{"huge_offset", [](PointCloud2& c) { c.fields[0].offset = 4'294'967'295u; },
                   "field 'x' (4 bytes at offset 4294967295)"},
        LyingCloud{"unknown_datatype", [](PointCloud2& c) { c.fields[1].datatype = 9; },
                   "field 'y' has an unknown datatype 9"},
        LyingCloud{"no_z", [](PointCloud2& c) { c.fields[2].name = "w"; }, "the cloud has no field 'z'"},
        LyingCloud{"point_step_zero", [](PointCloud2& c) { c.point_step = 0; c.row_step = 0; }, "point_step is 0"},
        LyingCloud{"rgb_past_point_step", [](PointCloud2& c) { c.fields[3].offset = 13; },
                   "field 'rgb' (4 bytes at offset 13)"}),
    [](const ::testing::TestParamInfo<LyingCloud>& info) { return std::string(info.param.name); });

TEST(LaserScanTest, ProjectsKeptRangesAsLaserGeometryDoes) {
  LaserScan scan;
  scan.frame_id = "laser";
  scan.angle_min = -static_cast<float>(M_PI) / 2;
  scan.angle_increment = static_cast<float>(M_PI) / 2;
  scan.range_min = 0.5f;
  scan.range_max = 10;
  const float inf = std::numeric_limits<float>::infinity();
  scan.ranges = {2, 0.2f, 3, 10, inf, std::numeric_limits<float>::quiet_NaN()};
  scan.intensities = {5, 6, 7};
  const PointCloud2 cloud = ProjectLaserScan(scan);
  ASSERT_EQ(cloud.width, 2u);   // 0.2 < range_min, 10 not < range_max, inf and NaN dropped
  const PointCloudReader reader(cloud);
  const int x = reader.Field("x"), y = reader.Field("y"), i = reader.Field("intensity");
  EXPECT_NEAR(reader.Value(x, 0), 0, 1e-6);
  EXPECT_NEAR(reader.Value(y, 0), -2, 1e-6);
  EXPECT_NEAR(reader.Value(x, 1), 0, 1e-6);   // beam 2 at -pi/2 + 2 * pi/2
  EXPECT_NEAR(reader.Value(y, 1), 3, 1e-6);
  EXPECT_EQ(reader.Value(i, 0), 5);
  EXPECT_EQ(reader.Value(i, 1), 7);
}

TEST(LaserScanTest, EachBeamIsPlacedAtItsOwnTimeAsTransformLaserScanToPointCloudDoes) {
  // three beams of 1 m straight ahead, 10 ms apart, while the frame moves 1 m along x and turns
  // 90 degrees: the middle beam gets half of both (slerp), the last all
  LaserScan scan;
  scan.frame_id = "laser";
  scan.stamp_ns = 5'000'000'000;
  scan.time_increment = 0.01f;
  scan.range_max = 10;
  scan.ranges = {1, 1, 1};
  EXPECT_EQ(LastBeamStamp(scan), 5'020'000'000);
  const Eigen::Isometry3d X_end = Eigen::Translation3d(1, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  const PointCloud2 cloud = ProjectLaserScan(scan, Eigen::Isometry3d::Identity(), X_end);
  EXPECT_EQ(cloud.frame_id, "");
  const PointCloudReader reader(cloud);
  const int x = reader.Field("x"), y = reader.Field("y");
  ASSERT_EQ(cloud.width, 3u);
  EXPECT_NEAR(reader.Value(x, 0), 1, 1e-6);
  EXPECT_NEAR(reader.Value(y, 0), 0, 1e-6);
  EXPECT_NEAR(reader.Value(x, 1), 0.5 + std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(reader.Value(y, 1), std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(reader.Value(x, 2), 1, 1e-6);
  EXPECT_NEAR(reader.Value(y, 2), 1, 1e-6);
  // a stamp of 0 (the latest transform) or a time_increment that is no number keeps the stamp
  scan.time_increment = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(LastBeamStamp(scan), scan.stamp_ns);
  scan.stamp_ns = 0;
  scan.time_increment = 0.01f;
  EXPECT_EQ(LastBeamStamp(scan), 0);
}

}  // namespace
}  // namespace urdfsnap::display
