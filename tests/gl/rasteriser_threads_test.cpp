// LeaveCoresToOtherThreads: LP_NUM_THREADS from the usable cores and the scene's triangles, and
// the user's own setting left alone (unit: sets the variable, makes no GL context).
#include "gl/rasteriser_threads.h"

#include <sched.h>
#include <stdlib.h>

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

namespace urdfsnap::gl {
namespace {

int Cores() {
  cpu_set_t set;
  EXPECT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
  return CPU_COUNT(&set);
}

class RasteriserThreadsTest : public ::testing::Test {
 protected:
  void TearDown() override { unsetenv("LP_NUM_THREADS"); }
  static std::string Variable() {
    const char* value = getenv("LP_NUM_THREADS");
    return value ? value : "(unset)";
  }
};

TEST_F(RasteriserThreadsTest, ALightSceneLeavesTheEncoderItsCores) {
  unsetenv("LP_NUM_THREADS");
  const std::string said = LeaveCoresToOtherThreads(1, kRasterBoundTriangles - 1);
  const std::string expected = std::to_string(std::max(0, Cores() - 2));
  EXPECT_EQ(Variable(), expected);
  EXPECT_EQ(said.rfind("LP_NUM_THREADS=" + expected + ": ", 0), 0u) << said;
  EXPECT_NE(said.find("1 core left to encoding"), std::string::npos) << said;
}

TEST_F(RasteriserThreadsTest, AHeavySceneRasterisesOnEveryCore) {
  unsetenv("LP_NUM_THREADS");
  const std::string said = LeaveCoresToOtherThreads(1, 135'000);
  EXPECT_EQ(Variable(), std::to_string(Cores()));
  EXPECT_NE(said.find("one per core: drawing 135000 triangles outweighs encoding"), std::string::npos) << said;
}

TEST_F(RasteriserThreadsTest, TheUsersSettingStands) {
  setenv("LP_NUM_THREADS", "3", 1);
  for (const std::size_t triangles : {std::size_t{0}, std::size_t{1'000'000}}) {
    EXPECT_EQ(LeaveCoresToOtherThreads(1, triangles), "");
    EXPECT_EQ(Variable(), "3");
  }
}

}  // namespace
}  // namespace urdfsnap::gl
