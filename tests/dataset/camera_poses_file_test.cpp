// ParseCameraPoses: the line format (spaces or commas, comments, blank lines), the quaternion
// normalised, and errors located at their line.
#include "dataset/camera_poses_file.h"

#include <utility>

#include <gtest/gtest.h>

#include "common/error.h"

namespace urdfsnap::dataset {
namespace {

std::string ErrorOf(const std::string& text) {
  try {
    ParseCameraPoses(text, "poses.txt");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CameraPosesFile, OnePosePerLineWithSpacesOrCommas) {
  const std::vector<Eigen::Isometry3d> poses =
      ParseCameraPoses("# x y z qx qy qz qw\n\n1 2 3 0 0 0 1\r\n  4,5,6,0,0,0,2\n-1 0 0.5 0, 0, 1, 1  \n", "p");
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_TRUE(poses[0].translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(poses[0].linear().isIdentity());
  EXPECT_TRUE(poses[1].translation().isApprox(Eigen::Vector3d(4, 5, 6)));
  EXPECT_TRUE(poses[1].linear().isIdentity(1e-12));   // (0, 0, 0, 2) normalised
  // 90° about z: x turns to y
  EXPECT_TRUE((poses[2].linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(poses[2].translation().isApprox(Eigen::Vector3d(-1, 0, 0.5)));
}

TEST(CameraPosesFile, ErrorsNameTheLine) {
  const std::string seven = "expected a camera pose: seven numbers X Y Z QX QY QZ QW";
  const std::pair<std::string, std::string> cases[] = {
      {"1 2 3 0 0 0 1\n1 2 3 0 0 1\n", "poses.txt:2: " + seven},
      {"# one\n1 2 3 0 0 0 1 8\n", "poses.txt:2: " + seven},
      {"1 2 nan 0 0 0 1\n", "poses.txt:1: " + seven},
      {"1 2 3 0 0 0 0\n", "poses.txt:1: the quaternion QX QY QZ QW is zero"},
      {"# nothing\n\n", "poses.txt: no camera pose in the file"},
      {"", "poses.txt: no camera pose in the file"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(ErrorOf(text), message) << text;
}

}  // namespace
}  // namespace urdfsnap::dataset
