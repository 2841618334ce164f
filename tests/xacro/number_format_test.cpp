// Python's spelling of numbers: float repr, int str, int()/float() of text, round().
#include "xacro/internal/number_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace urdfsnap::xacro {
namespace {

TEST(FormatFloat, MatchesPythonRepr) {
  const std::pair<double, const char*> cases[] = {
      {0.1 + 0.2, "0.30000000000000004"}, {0.3 * 3, "0.8999999999999999"},
      {std::sin(M_PI), "1.2246467991473532e-16"}, {10.0 / 2, "5.0"}, {1e-5, "1e-05"},
      {1e-4, "0.0001"}, {1e16, "1e+16"}, {1e15, "1000000000000000.0"}, {1e22, "1e+22"},
      {-0.0, "-0.0"}, {0.0, "0.0"}, {1.5e-5, "1.5e-05"}, {2.5e-4, "0.00025"}, {100.0, "100.0"},
      {1.0 / 3, "0.3333333333333333"}, {123456789.0 * 10, "1234567890.0"}, {-2.5, "-2.5"},
      {9007199254740992.0, "9007199254740992.0"}, {1.7976931348623157e308, "1.7976931348623157e+308"},
      {5e-324, "5e-324"}, {HUGE_VAL, "inf"}, {-HUGE_VAL, "-inf"}, {123.456, "123.456"},
  };
  for (const auto& [value, expected] : cases) EXPECT_EQ(FormatFloat(value), expected) << expected;
  EXPECT_EQ(FormatFloat(NAN), "nan");
}

TEST(FormatInt, ExactFor128Bits) {
  EXPECT_EQ(FormatInt(0), "0");
  EXPECT_EQ(FormatInt(-17), "-17");
  EXPECT_EQ(FormatInt(Int(1) << 64), "18446744073709551616");
  EXPECT_EQ(FormatInt(std::numeric_limits<Int>::min()), "-170141183460469231731687303715884105728");
}

TEST(ParseIntText, AcceptsWhatPythonIntAccepts) {
  EXPECT_EQ(ParseIntText("007"), Int(7));
  EXPECT_EQ(ParseIntText("  8  "), Int(8));
  EXPECT_EQ(ParseIntText("+3"), Int(3));
  EXPECT_EQ(ParseIntText("-42"), Int(-42));
  EXPECT_EQ(ParseIntText("1_000"), Int(1000));
  for (const char* bad : {"0x1F", "1.0", "", " ", "1__0", "_1", "1_", "1e3", "abc", "--1"}) {
    EXPECT_FALSE(ParseIntText(bad)) << bad;
  }
}

TEST(ParseFloatText, AcceptsWhatPythonFloatAccepts) {
  EXPECT_EQ(ParseFloatText(".5"), 0.5);
  EXPECT_EQ(ParseFloatText("5."), 5.0);
  EXPECT_EQ(ParseFloatText("1e3"), 1000.0);
  EXPECT_EQ(ParseFloatText(" -2.5E-1 "), -0.25);
  EXPECT_TRUE(std::isinf(*ParseFloatText("Infinity")));
  EXPECT_TRUE(std::isnan(*ParseFloatText("NaN")));
  EXPECT_TRUE(std::signbit(*ParseFloatText("-0.0")));
  for (const char* bad : {"", ".", "e3", "1e", "0 0 1", "1.5.2", "0x10", "1,5"}) {
    EXPECT_FALSE(ParseFloatText(bad)) << bad;
  }
}

TEST(RoundFloat, CorrectlyRoundedLikePython) {
  EXPECT_EQ(RoundFloat(2.675, 2), 2.67);  // 2.675 is 2.67499999... in binary
  EXPECT_EQ(RoundFloat(1.0 / 3, 3), 0.333);
  EXPECT_EQ(RoundFloat(0.125, 2), 0.12);  // exact tie: to even
  EXPECT_EQ(RoundFloat(1234.5, -2), 1200.0);
}

}  // namespace
}  // namespace urdfsnap::xacro
