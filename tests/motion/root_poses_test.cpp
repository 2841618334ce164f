// Where TF places the robot's root in a fixed frame outside it: the lookup at the trajectory's
// time (its stamp at time 0 plus t), one warning for frames outside the recorded transforms, and
// the error for a fixed frame TF does not connect to the root.
#include "motion/root_poses.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/error_text.h"

namespace urdfsnap::motion {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// odom -> base_link moving 1 m along +x from stamp 100 s to 101 s
std::shared_ptr<const tf::TfBuffer> Drive() {
  auto buffer = std::make_shared<tf::TfBuffer>();
  buffer->Add({"odom", "base_link", 100'000'000'000, {0, 0, 0}, Eigen::Quaterniond::Identity()},
             false, "drive");
  buffer->Add({"odom", "base_link", 101'000'000'000, {1, 0, 0}, Eigen::Quaterniond::Identity()},
             false, "drive");
  return buffer;
}

TEST(RootPosesTest, PlacesTheRootWhereTfSaysAtTheTrajectorysTime) {
  const RootPoses root(Drive(), "odom", "base_link", 100.0, "run.mcap");
  Warnings warnings;
  EXPECT_TRUE(root.At(0.25, warnings).translation().isApprox(Eigen::Vector3d(0.25, 0, 0)));
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(root.At(3, warnings).translation().isApprox(Eigen::Vector3d(1, 0, 0)));
  root.At(4, warnings);
  EXPECT_THAT(warnings.messages(),
              ElementsAre(HasSubstr("run.mcap: TF from 'odom' to 'base_link' is not recorded at "
                                    "some frames' times")));
}

TEST(RootPosesTest, AFixedFrameTfDoesNotConnectIsAnError) {
  EXPECT_THAT(test::ErrorText([] { RootPoses(Drive(), "map", "base_link", 100.0, "run.mcap"); }),
              HasSubstr("--fixed-frame 'map': neither a link of the robot nor a frame that "
                        "run.mcap's /tf and /tf_static connect to its root link 'base_link' (its "
                        "TF frames: 'odom', 'base_link')"));
}

}  // namespace
}  // namespace urdfsnap::motion
