// The Camera display's image as time moves forward: of the images received by a moment, the one
// with the latest stamp not after it; one stamped ahead of its receipt waits for its stamp, a few
// at most; an older stamp received later does not replace a newer one.
#include "display/camera_image_display.h"

#include <gtest/gtest.h>

#include "bag/cdr_message.h"
#include "support/cdr_bytes.h"

namespace urdfsnap::display {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

// A 1x1 mono8 sensor_msgs/Image stamped `stamp_ns` whose one pixel is `grey`.
bag::MessageValue Image(std::int64_t stamp_ns, std::uint8_t grey) {
  static const bag::MessageSchema schema = *bag::MessageSchema::Shipped("sensor_msgs/msg/Image");
  test::CdrBytes cdr;
  cdr.I32(static_cast<std::int32_t>(stamp_ns / kSecond)).U32(static_cast<std::uint32_t>(stamp_ns % kSecond)).Str("camera");
  cdr.U32(1).U32(1).Str("mono8").U8(0).U32(1).U32(1).U8(grey);
  return bag::DecodeMessage(schema, cdr.bytes());
}

class CameraImageDisplayTest : public ::testing::Test {
 protected:
  void Receive(std::int64_t stamp_ns, std::uint8_t grey, std::int64_t received_ns) {
    display_.Receive(Image(stamp_ns, grey), received_ns, "message " + std::to_string(grey), warnings_);
  }
  // The grey of the picture shown at `time_ns`, -1 for none.
  int ShownAt(std::int64_t time_ns) {
    const std::optional<CameraImageDisplay::Picture> shown = display_.Shown(time_ns);
    return shown ? shown->image->rgb[0] : -1;
  }
  CameraImageDisplay display_{"/camera"};
  Warnings warnings_;
};

TEST_F(CameraImageDisplayTest, ReadsBothImageTypes) {
  EXPECT_TRUE(display_.Reads("sensor_msgs/msg/Image"));
  EXPECT_TRUE(display_.Reads("sensor_msgs/msg/CompressedImage"));
  EXPECT_FALSE(display_.Reads("sensor_msgs/msg/CameraInfo"));
  EXPECT_EQ(display_.topic(), "/camera");
}

TEST_F(CameraImageDisplayTest, TheLatestStampReceivedIsShown) {
  EXPECT_EQ(ShownAt(0), -1);
  Receive(1 * kSecond, 10, 1 * kSecond + 100);
  EXPECT_EQ(ShownAt(2 * kSecond), 10);
  Receive(3 * kSecond, 30, 3 * kSecond + 100);
  Receive(2 * kSecond, 20, 3 * kSecond + 200);   // older, received later: not shown
  EXPECT_EQ(ShownAt(4 * kSecond), 30);
  Receive(0, 40, 5 * kSecond);                   // no stamp: its receipt's time
  EXPECT_EQ(ShownAt(5 * kSecond), 40);
}

TEST_F(CameraImageDisplayTest, AnImageStampedAheadWaitsForItsStamp) {
  Receive(1 * kSecond, 10, 1 * kSecond);
  Receive(4 * kSecond, 40, 2 * kSecond);   // stamped ahead of its receipt
  EXPECT_EQ(ShownAt(3 * kSecond), 10);
  EXPECT_EQ(ShownAt(4 * kSecond), 40);
  // at most kWaiting wait: the oldest is dropped
  for (int k = 0; k <= static_cast<int>(CameraImageDisplay::kWaiting); ++k) {
    Receive((10 + k) * kSecond, static_cast<std::uint8_t>(100 + k), 5 * kSecond);
  }
  EXPECT_EQ(ShownAt(10 * kSecond), 40);    // picture 100 was dropped
  EXPECT_EQ(ShownAt(11 * kSecond), 101);
}

}  // namespace
}  // namespace urdfsnap::display
