// PointCloud2 and LaserScan messages from a bag written by other tools (tests/node/
// make_cloud_bags.mjs: @mcap/core and Foxglove's CDR serialiser), decoded by the bag's own schema
// and drawn by RViz's rules; the same messages in a .db3 without definitions, decoded by the .msg
// texts urdfsnap ships; and the bag whose cloud claims 10^8 points over 16 bytes.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "bag/bag_messages.h"
#include "bag/cdr_message.h"
#include "bag/test_bags.h"
#include "display/laser_scan.h"
#include "display/point_cloud.h"
#include "display/point_cloud_reader.h"
#include "support/error_text.h"

namespace urdfsnap::display {
namespace {

// The last message of each display topic of `bag`, decoded, with the definitions they point into.
struct Decoded {
  std::map<std::string, bag::MessageValue> messages;
  std::vector<std::shared_ptr<const bag::MessageSchema>> schemas;
  const bag::MessageValue& at(const std::string& topic) const { return messages.at(topic); }
};

Decoded Messages(const std::string& bag) {
  Decoded decoded;
  bag::ReadBagMessages(
      test::TestBag(bag),
      [](const bag::BagTopic& topic) {
        return topic.name == "/cloud_rgb" || topic.name == "/cloud_intensity" || topic.name == "/scan";
      },
      [&](const bag::BagMessage& message) {
        decoded.schemas.push_back(message.topic.schema);
        decoded.messages[message.topic.name] = bag::DecodeMessage(*message.topic.schema, message.data);
      });
  return decoded;
}

// clouds.mcap carries its definitions; clouds.db3, as rosbag2 before Jazzy writes SQLite, none
class PointCloudBagTest : public ::testing::TestWithParam<const char*> {};

TEST_P(PointCloudBagTest, CloudsAndScanFromABagWrittenByOtherTools) {
  const auto messages = Messages(GetParam());
  const PointCloud2 rgb = DecodePointCloud2(messages.at("/cloud_rgb"));
  EXPECT_EQ(rgb.frame_id, "base_link");
  EXPECT_EQ(rgb.stamp_ns, 1'000'000'000);
  EXPECT_EQ(rgb.width, 400u);
  EXPECT_EQ(rgb.data.size(), 400u * 16);
  const scene::PointSet wall = CloudPointSet(rgb, {}, Eigen::Isometry3d::Identity());
  ASSERT_EQ(wall.positions.size(), 400u);
  EXPECT_TRUE(wall.positions[0].isApprox(Eigen::Vector3f(1.5f, -0.5f, 0.2f)));
  EXPECT_TRUE(wall.colours[0].isApprox(Eigen::Vector4f(1, 80 / 255.f, 0, 1)));   // RGB8, chosen by RViz's rule

  const scene::PointSet ring = CloudPointSet(DecodePointCloud2(messages.at("/cloud_intensity")), {},
                                             Eigen::Isometry3d::Identity());
  ASSERT_EQ(ring.positions.size(), 360u);
  EXPECT_TRUE(ring.colours[0].isApprox(Eigen::Vector4f(1, 0, 0, 1)));     // intensity 0: the minimum, red
  EXPECT_TRUE(ring.colours[359].isApprox(Eigen::Vector4f(1, 0, 1, 1)));   // 359: the maximum, magenta

  const LaserScan scan = DecodeLaserScan(messages.at("/scan"));
  EXPECT_EQ(scan.frame_id, "lidar");
  ASSERT_EQ(scan.ranges.size(), 181u);
  const PointCloud2 projected = ProjectLaserScan(scan);
  EXPECT_EQ(projected.width, 181u - 7);   // every 30th beam is infinite
  EXPECT_NE(PointCloudReader(projected).Find("intensity"), -1);
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutDefinitions, PointCloudBagTest,
                         ::testing::Values("clouds.mcap", "clouds.db3"),
                         [](const ::testing::TestParamInfo<const char*>& bag) {
                           return std::string(bag.param).substr(std::string(bag.param).find('.') + 1);
                         });

TEST(PointCloudLiarTest, CloudClaimingAHundredMillionPointsIsAnErrorNotAnAllocation) {
  const Decoded decoded = Messages("cloud_lies.mcap");
  const PointCloud2 liar = DecodePointCloud2(decoded.at("/cloud_rgb"));
  EXPECT_EQ(liar.width, 100'000'000u);
  EXPECT_THAT(test::ErrorText<CloudError>([&] { CloudPointSet(liar, {}, Eigen::Isometry3d::Identity()); }),
              ::testing::HasSubstr("data holds 16 bytes, fewer than the 1600000000"));
}

}  // namespace
}  // namespace urdfsnap::display
