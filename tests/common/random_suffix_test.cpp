// Random temporary names: six lower-case letters and digits, different from call to call (unit).
#include "common/random_suffix.h"

#include <gtest/gtest.h>

#include <set>

namespace urdfsnap {
namespace {

TEST(RandomSuffix, SixLowerCaseLettersAndDigitsThatDiffer) {
  std::set<std::string> seen;
  for (int i = 0; i < 100; ++i) {
    const std::string suffix = RandomSuffix();
    ASSERT_EQ(suffix.size(), 6u);
    for (const char c : suffix) EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) << suffix;
    seen.insert(suffix);
  }
  EXPECT_GT(seen.size(), 95u);  // 36^6 names: a repeat in 100 is a one in ten thousand chance
}

}  // namespace
}  // namespace urdfsnap
