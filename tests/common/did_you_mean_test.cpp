// DidYouMean: which misspellings get a hint, and which candidate it names.
#include "common/did_you_mean.h"

#include <gtest/gtest.h>

namespace urdfsnap {
namespace {

TEST(DidYouMeanTest, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(EditDistance("", ""), 0u);
  EXPECT_EQ(EditDistance("yaw", "yaw"), 0u);
  EXPECT_EQ(EditDistance("yaw", "yaww"), 1u);
  EXPECT_EQ(EditDistance("pitch", "ptich"), 2u);
  EXPECT_EQ(EditDistance("render", ""), 6u);
}

TEST(DidYouMeanTest, NamesTheNearestCandidate) {
  const std::vector<std::string> options = {"--yaw", "--pitch", "--distance", "--focal"};
  EXPECT_EQ(DidYouMean("--yaww", options), "did you mean '--yaw'? ");
  EXPECT_EQ(DidYouMean("--distnace", options), "did you mean '--distance'? ");
  EXPECT_EQ(DidYouMean("--ptich", options), "did you mean '--pitch'? ");
}

TEST(DidYouMeanTest, GivesNoHintForUnrelatedOrShortWords) {
  const std::vector<std::string> options = {"--yaw", "--pitch", "-o", "-j"};
  EXPECT_EQ(DidYouMean("--banana", options), "");
  EXPECT_EQ(DidYouMean("-x", options), "");   // one edit is half of a two-letter word
  EXPECT_EQ(DidYouMean("anything", {}), "");
}

}  // namespace
}  // namespace urdfsnap
