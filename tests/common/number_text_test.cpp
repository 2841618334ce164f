// FormatBytes and FormatForPeople: file sizes and numbers in messages as people read them.
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

TEST(FormatForPeopleTest, RoundsAwayFloatNoiseAndKeepsWholeDigits) {
  EXPECT_EQ(FormatForPeople(0.5999974410156591), "0.6");
  EXPECT_EQ(FormatForPeople(0.6000000238418579, "rad"), "0.6 rad");
  EXPECT_EQ(FormatForPeople(2.8973, "rad"), "2.8973 rad");
  EXPECT_EQ(FormatForPeople(-3.14159265), "-3.1416");
  EXPECT_EQ(FormatForPeople(12345.678, "s"), "12346 s");
  EXPECT_EQ(FormatForPeople(1734567890.25, "s"), "1734567890 s");
  EXPECT_EQ(FormatForPeople(9.999999), "10");
  EXPECT_EQ(FormatForPeople(0), "0");
  EXPECT_EQ(FormatForPeople(-0.0), "0");
  EXPECT_EQ(FormatForPeople(1.5e-7, "m"), "1.5e-07 m");
  EXPECT_EQ(FormatRangeForPeople(-2.8973, 2.8973, "rad"), "-2.8973 to 2.8973 rad");
}

}  // namespace
}  // namespace urdfsnap
