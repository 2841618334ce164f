// /tf and /tf_static read from bags of the MCAP project's writer: the same tree from MCAP (with
// definitions) and SQLite (with urdfsnap's), static transforms at every time, and broken trees
// located at their message.
#include "tf/bag_transforms.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "support/error_text.h"

namespace urdfsnap::tf {
namespace {

using ::testing::HasSubstr;

// tests/node/make_test_bags.mjs: odom -> base_link at x = 0.1 i m, yaw = 0.1 i rad, 100 ms apart
constexpr std::int64_t kStart = test::kBagStartNanoseconds;

TEST(BagTransformsTest, BothStoragesGiveTheRecordedTree) {
  for (const char* bag : {"tf_drive.mcap", "tf_drive.db3"}) {
    SCOPED_TRACE(bag);
    const TfBuffer buffer = ReadBagTransforms(test::TestBag(bag));
    EXPECT_EQ(buffer.ParentOf("laser"), "base_link");
    EXPECT_EQ(buffer.ParentOf("base_link"), "odom");
    // half-way between samples 4 and 5: x = 0.45, yaw = 0.45
    const Lookup base = *buffer.Find("odom", "base_link", kStart + 450'000'000);
    EXPECT_FALSE(base.extrapolated);
    EXPECT_TRUE(base.X_TS.translation().isApprox(Eigen::Vector3d(0.45, 0, 0), 1e-12));
    EXPECT_NEAR(Eigen::AngleAxisd(base.X_TS.linear()).angle(), 0.45, 1e-12);
    // the laser, static, at the end of the drive
    const Lookup laser = *buffer.Find("odom", "laser", kStart + 1'000'000'000);
    const Eigen::Vector3d expected =
        Eigen::Vector3d(1, 0, 0) + Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()) *
                                       Eigen::Vector3d(0.1, 0, 0.3);
    EXPECT_TRUE(laser.X_TS.translation().isApprox(expected, 1e-12));
  }
}

TEST(BagTransformsTest, TheRoverSampleDrivesItsLoop) {
  // rover_loop.mcap: a circle of 1 m radius about (0, 1) in 8 s, starting at the origin heading +x
  const TfBuffer buffer = ReadBagTransforms(test::TestBag("rover_loop.mcap"));
  const Lookup half = *buffer.Find("odom", "base_link", kStart + 4'000'000'000);
  EXPECT_TRUE(half.X_TS.translation().isApprox(Eigen::Vector3d(0, 2, 0), 1e-9));
  EXPECT_TRUE(half.X_TS.linear().col(0).isApprox(Eigen::Vector3d(-1, 0, 0), 1e-9));
  // between two samples (every 50 ms) the base stays on the circle to within the chord's sagitta
  const Lookup between = *buffer.Find("odom", "base_link", kStart + 1'025'000'000);
  EXPECT_NEAR((between.X_TS.translation() - Eigen::Vector3d(0, 1, 0)).norm(), 1, 1e-3);
  EXPECT_FALSE(between.extrapolated);
}

TEST(BagTransformsTest, ABagWithoutTfHasAnEmptyTree) {
  EXPECT_TRUE(ReadBagTransforms(test::TestBag("split_bag")).frames().empty());
}

TEST(BagTransformsTest, BrokenTreesAreOneErrorAtTheirMessage) {
  const std::pair<const char*, const char*> cases[] = {
      {"tf_nan.mcap", "tf_nan.mcap: message 3 on '/tf' (log time 1700000000.200000000 s): "
                      "transform 'odom' -> 'base_link': a NaN or infinite value"},
      {"tf_loop.mcap", "tf_loop.mcap: message 4 on '/tf' (log time 1700000000.300000000 s): "
                       "transform 'laser' -> 'odom': a loop"},
      {"tf_two_parents.mcap", "message 5 on '/tf' (log time 1700000000.400000000 s): transform "
                              "'map' -> 'base_link': frame 'base_link' already has the parent "
                              "'odom'"},
      {"tf_backwards.mcap", "message 6 on '/tf' (log time 1700000000.500000000 s): transform "
                            "'odom' -> 'base_link': stamped 1700000000000000000 ns, before"},
  };
  for (const auto& [bag_, error] : cases) {
    const auto& bag = bag_;   // clang 14 cannot capture a structured binding
    SCOPED_TRACE(bag);
    EXPECT_THAT(test::ErrorText([&] { ReadBagTransforms(test::TestBag(bag)); }), HasSubstr(error));
  }
}

}  // namespace
}  // namespace urdfsnap::tf
