// FormatBytes: file sizes as people read them.
#include "common/number_text.h"

#include <gtest/gtest.h>

namespace urdfsnap {
namespace {

TEST(FormatBytesTest, RoundsToTwoOrThreeDigitsInSiUnits) {
  EXPECT_EQ(FormatBytes(0), "0 bytes");
  EXPECT_EQ(FormatBytes(1), "1 byte");
  EXPECT_EQ(FormatBytes(999), "999 bytes");
  EXPECT_EQ(FormatBytes(1000), "1.0 kB");
  EXPECT_EQ(FormatBytes(834'200), "834 kB");
  EXPECT_EQ(FormatBytes(999'600), "1.0 MB");   // not "1000 kB"
  EXPECT_EQ(FormatBytes(1'234'567), "1.2 MB");
  EXPECT_EQ(FormatBytes(12'345'678), "12 MB");
  EXPECT_EQ(FormatBytes(3'400'000'000ull), "3.4 GB");
}

}  // namespace
}  // namespace urdfsnap
