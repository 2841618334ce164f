// The CPU's mipmap levels (gl/internal/mip_levels.h), without GL: which sizes they follow llvmpipe
// for, how many levels a chain has, and the rounded-up averages, rows first, of a level below.
#include "gl/internal/mip_levels.h"

#include <gtest/gtest.h>

namespace urdfsnap::gl {
namespace {

// A width x height RGBA texture whose every channel of texel i is values[i].
std::vector<std::uint8_t> Grey(const std::vector<std::uint8_t>& values) {
  std::vector<std::uint8_t> texels;
  for (const std::uint8_t value : values) texels.insert(texels.end(), 4, value);
  return texels;
}

TEST(MipLevelsTest, FollowsLlvmpipeWhereEverySideIsEvenOneOrThree) {
  EXPECT_TRUE(MipLevelsExact(1024, 1024));
  EXPECT_TRUE(MipLevelsExact(768, 768));     // ... 6, 3, 1
  EXPECT_TRUE(MipLevelsExact(48, 12));       // 24x6, 12x3, 6x1, 3x1, 1x1
  EXPECT_TRUE(MipLevelsExact(1, 1));
  EXPECT_FALSE(MipLevelsExact(5, 8));        // 5 to 2 samples between texels
  EXPECT_FALSE(MipLevelsExact(40, 40));      // 40, 20, 10, 5
  EXPECT_FALSE(MipLevelsExact(0, 4));
}

TEST(MipLevelsTest, CountsLevelsDownToOneByOne) {
  EXPECT_EQ(MipLevelCount(1024, 1024), 11);
  EXPECT_EQ(MipLevelCount(768, 768), 10);
  EXPECT_EQ(MipLevelCount(12, 6), 4);
  EXPECT_EQ(MipLevelCount(1, 1), 1);
}

TEST(MipLevelsTest, AveragesRoundedUpAlongRowsThenBetweenThem) {
  // (0, 1 | 1, 1): the rows' averages 1 and 1, not the mean 0.75 rounded
  EXPECT_EQ(NextMipLevel(Grey({0, 1, 1, 1}), 2, 2), Grey({1}));
  // (10, 13 | 20, 0): rows 12 and 10, then 11
  EXPECT_EQ(NextMipLevel(Grey({10, 13, 20, 0}), 2, 2), Grey({11}));
  // each channel on its own, no carry between bytes
  EXPECT_EQ(NextMipLevel({255, 0, 1, 254, 255, 1, 2, 255}, 2, 1), (std::vector<std::uint8_t>{255, 1, 2, 255}));
}

TEST(MipLevelsTest, TakesTheMiddleOfThreeAndTheOnlyTexelOfOne) {
  EXPECT_EQ(NextMipLevel(Grey({7, 50, 9}), 3, 1), Grey({50}));
  EXPECT_EQ(NextMipLevel(Grey({7, 50, 9}), 1, 3), Grey({50}));
  // 4x3 to 2x1: the middle row, its pairs averaged
  EXPECT_EQ(NextMipLevel(Grey({0, 0, 0, 0, 4, 7, 100, 200, 0, 0, 0, 0}), 4, 3), Grey({6, 150}));
}

}  // namespace
}  // namespace urdfsnap::gl
