// TfBuffer by invariants: static and dynamic transforms chained to a common root, linear
// translation and slerp rotation between samples, extrapolation flagged, and one located error for
// each way a tree can be broken.
#include "tf/tf_buffer.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap::tf {
namespace {

using ::testing::HasSubstr;

constexpr std::int64_t kSecond = 1'000'000'000;

StampedTransform Make(const std::string& parent, const std::string& child, std::int64_t stamp,
                      Eigen::Vector3d translation, double yaw = 0) {
  return {parent, child, stamp, translation,
          Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))};
}

// odom -> base_link driving +x and turning, base_link -> laser static
TfBuffer Robot() {
  TfBuffer buffer;
  buffer.Add(Make("base_link", "laser", 0, {0.1, 0, 0.3}), true, "static");
  buffer.Add(Make("odom", "base_link", 1 * kSecond, {0, 0, 0}, 0), false, "m1");
  buffer.Add(Make("odom", "base_link", 3 * kSecond, {2, 0, 0}, std::numbers::pi / 2), false, "m2");
  return buffer;
}

TEST(TfBufferTest, InterpolatesTranslationLinearlyAndRotationBySlerp) {
  const TfBuffer buffer = Robot();
  const std::optional<Lookup> half = buffer.Find("odom", "base_link", 2 * kSecond);
  ASSERT_TRUE(half.has_value());
  EXPECT_FALSE(half->extrapolated);
  EXPECT_TRUE(half->X_TS.translation().isApprox(Eigen::Vector3d(1, 0, 0)));
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(half->X_TS.linear().isApprox(expected, 1e-12));
}

TEST(TfBufferTest, ChainsStaticAndDynamicTransformsBothWays) {
  const TfBuffer buffer = Robot();
  // at 3 s the base is at x = 2 facing +y: the laser 0.1 ahead of it is at (2, 0.1, 0.3)
  const Lookup laser = *buffer.Find("odom", "laser", 3 * kSecond);
  EXPECT_TRUE(laser.X_TS.translation().isApprox(Eigen::Vector3d(2, 0.1, 0.3)));
  const Lookup back = *buffer.Find("laser", "odom", 3 * kSecond);
  EXPECT_TRUE((back.X_TS * laser.X_TS).isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  EXPECT_TRUE(buffer.Find("laser", "laser", 0)->X_TS.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_EQ(buffer.ParentOf("laser"), "base_link");
  EXPECT_EQ(buffer.ParentOf("odom"), "");
  EXPECT_EQ(buffer.frames(), (std::vector<std::string>{"base_link", "laser", "odom"}));
}

TEST(TfBufferTest, OutsideTheSamplesHoldsTheNearestAndSaysSo) {
  const TfBuffer buffer = Robot();
  const Lookup before = *buffer.Find("odom", "base_link", 0);
  EXPECT_TRUE(before.extrapolated);
  EXPECT_TRUE(before.X_TS.translation().isZero());
  const Lookup after = *buffer.Find("odom", "base_link", 9 * kSecond);
  EXPECT_TRUE(after.extrapolated);
  EXPECT_TRUE(after.X_TS.translation().isApprox(Eigen::Vector3d(2, 0, 0)));
  // static transforms hold at every time
  EXPECT_FALSE(buffer.Find("base_link", "laser", 100 * kSecond)->extrapolated);
}

TEST(TfBufferTest, UnknownOrUnconnectedFramesFindNothing) {
  TfBuffer buffer = Robot();
  buffer.Add(Make("map", "other_robot", 0, {1, 1, 0}), true, "static");
  EXPECT_FALSE(buffer.Find("odom", "gripper", kSecond).has_value());
  EXPECT_FALSE(buffer.Find("odom", "other_robot", kSecond).has_value());
}

TEST(TfBufferTest, RepeatedStampsAreSkippedAndTheLatestStaticHolds) {
  TfBuffer buffer = Robot();
  buffer.Add(Make("odom", "base_link", 3 * kSecond, {5, 5, 5}), false, "repeat");
  EXPECT_TRUE(buffer.Find("odom", "base_link", 3 * kSecond)->X_TS.translation().isApprox(
      Eigen::Vector3d(2, 0, 0)));
  buffer.Add(Make("base_link", "laser", 0, {0.2, 0, 0.3}), true, "static again");
  EXPECT_TRUE(buffer.Find("base_link", "laser", 0)->X_TS.translation().isApprox(
      Eigen::Vector3d(0.2, 0, 0.3)));
}

TEST(TfBufferTest, BrokenTreesAreOneLocatedErrorEach) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  StampedTransform nan_rotation = Make("odom", "base_link", 4 * kSecond, {0, 0, 0});
  nan_rotation.rotation = Eigen::Quaterniond(nan, 0, 0, 0);
  StampedTransform zero_rotation = Make("odom", "base_link", 4 * kSecond, {0, 0, 0});
  zero_rotation.rotation = Eigen::Quaterniond(0, 0, 0, 0);
  const std::pair<StampedTransform, std::string> cases[] = {
      {nan_rotation, "bag: transform 'odom' -> 'base_link': a NaN or infinite value"},
      {zero_rotation, "the quaternion (0.000000, 0.000000, 0.000000, 0.000000) is not of unit "
                      "length"},
      {Make("map", "base_link", 4 * kSecond, {0, 0, 0}),
       "frame 'base_link' already has the parent 'odom'; a frame has one parent"},
      {Make("laser", "odom", 4 * kSecond, {0, 0, 0}), "a loop: 'laser' descends from 'odom'"},
      {Make("odom", "base_link", 2 * kSecond, {0, 0, 0}),
       "stamped 2000000000 ns, before the frame's previous stamp 3000000000 ns"},
      {Make("odom", "odom", 4 * kSecond, {0, 0, 0}), "a frame that is its own parent"},
      {Make("", "x", 4 * kSecond, {0, 0, 0}), "a frame without a name"},
  };
  for (const auto& [transform_, error] : cases) {
    const auto& transform = transform_;   // clang 14 cannot capture a structured binding
    SCOPED_TRACE(error);
    TfBuffer buffer = Robot();
    EXPECT_THAT(test::ErrorText([&] { buffer.Add(transform, false, "bag"); }), HasSubstr(error));
  }
  TfBuffer buffer = Robot();
  EXPECT_THAT(test::ErrorText([&] {
                buffer.Add(Make("odom", "base_link", 0, {0, 0, 0}), true, "bag");
              }),
              HasSubstr("frame 'base_link' has both static and dynamic transforms"));
}

}  // namespace
}  // namespace urdfsnap::tf
