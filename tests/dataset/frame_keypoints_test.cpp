// Keypoint visibility against depth and label images: hidden only by another link's surface in
// front of the point; points behind the camera or outside the image are not in it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dataset/frame_keypoints.h"

namespace urdfsnap::dataset {
namespace {

constexpr const char* kRobot = R"(<robot name="r">
  <link name="a"/><link name="b"/>
  <joint name="ab" type="fixed"><parent link="a"/><child link="b"/><origin xyz="0.1 0 0"/></joint>
</robot>)";

TEST(FrameKeypoints, VisibilityFromDepthAndLabels) {
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(kRobot, "r.urdf", warnings);
  // a 4x2 camera with a 90° field of view (fx = fy = 1, principal point (1.5, 0.5)), 1 m behind
  // link a, looking along +x
  const camera::CameraModel camera(std::numbers::pi / 2, 4, 2, {});
  Eigen::Isometry3d X_RC = Eigen::Isometry3d::Identity();
  X_RC.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;   // optical z = +x, x = −y, y = −z
  X_RC.translation() = Eigen::Vector3d(-1, 0, 0);
  const std::vector<Eigen::Isometry3d> X_RL = {Eigen::Isometry3d::Identity(),
                                               Eigen::Isometry3d(Eigen::Translation3d(0.1, 0, 0))};
  // both points land on the image centre (u = 1.5, v = 0.5: pixel (2, 1) by rounding half away)
  image::DepthImage depth{4, 2, std::vector<float>(8, std::nanf(""))};
  image::LabelImage labels{4, 2, std::vector<std::uint16_t>(8, 0)};
  const auto project = [&] { return ProjectKeypoints(robot, X_RL, X_RC, camera, depth, labels); };
  std::vector<FrameKeypoint> k = project();
  ASSERT_EQ(k.size(), 3u);
  EXPECT_EQ(k[0].name, "a");
  EXPECT_EQ(k[2].kind, FrameKeypoint::Kind::kJoint);
  EXPECT_DOUBLE_EQ(k[0].depth, 1);
  EXPECT_DOUBLE_EQ(k[1].depth, 1.1);
  EXPECT_NEAR(k[0].uv->x(), 1.5, 1e-12);
  EXPECT_TRUE(k[0].in_image && k[0].visible && k[1].visible);   // nothing drawn there
  // a surface of link a 5 cm in front of b: b is hidden, a (its own link) and the joint a-b not
  depth.metres[1 * 4 + 2] = 1.05f;
  labels.labels[1 * 4 + 2] = 1;
  k = project();
  EXPECT_TRUE(k[0].visible);
  EXPECT_FALSE(k[1].visible);
  EXPECT_TRUE(k[1].in_image);
  EXPECT_TRUE(k[2].visible);
  // a camera facing away sees nothing
  X_RC.linear() = -X_RC.linear();
  X_RC.linear().col(0) = -X_RC.linear().col(0);
  k = project();
  EXPECT_FALSE(k[0].uv);
  EXPECT_FALSE(k[0].in_image);
  EXPECT_FALSE(k[0].visible);
}

}  // namespace
}  // namespace urdfsnap::dataset
