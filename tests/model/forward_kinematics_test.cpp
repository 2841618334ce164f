// Forward kinematics against transforms worked out by hand for every joint type, mimic joints
// and the mrm arm at a pose.
#include "model/forward_kinematics.h"

#include <cmath>

#include <gtest/gtest.h>

#include "common/error.h"
#include "model/joint_values.h"
#include "test_robots.h"

namespace urdfsnap::model {
namespace {

using Eigen::AngleAxisd;
using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Translation3d;
using Eigen::Vector3d;

constexpr double kTolerance = 1e-12;

void ExpectPoseNear(const Isometry3d& expected, const Isometry3d& actual) {
  EXPECT_TRUE(actual.matrix().isApprox(expected.matrix(), kTolerance))
      << "expected\n" << expected.matrix() << "\nactual\n" << actual.matrix();
}

Matrix3d RotX(double a) { return AngleAxisd(a, Vector3d::UnitX()).toRotationMatrix(); }
Matrix3d RotY(double a) { return AngleAxisd(a, Vector3d::UnitY()).toRotationMatrix(); }
Matrix3d RotZ(double a) { return AngleAxisd(a, Vector3d::UnitZ()).toRotationMatrix(); }

Isometry3d Pose(const Vector3d& p, const Matrix3d& R) {
  Isometry3d X = Isometry3d::Identity();
  X.translation() = p;
  X.linear() = R;
  return X;
}

class EveryJointTest : public ::testing::Test {
 protected:
  EveryJointTest() : robot_(LoadRobot(test::kEveryJointUrdf, "kinds.urdf", warnings_)) {}

  Isometry3d PoseOf(const std::vector<Isometry3d>& X_RL, const char* link) const {
    const int index = robot_.FindLink(link);
    EXPECT_GE(index, 0) << link;
    return X_RL[index];
  }

  Warnings warnings_;
  Robot robot_;
};

TEST_F(EveryJointTest, LinksAreInTreeOrder) {
  ASSERT_EQ(robot_.links().size(), 8u);
  EXPECT_EQ(robot_.links()[0].name, "base");
  for (size_t i = 1; i < robot_.links().size(); ++i) {
    const Joint& joint = robot_.joints()[robot_.links()[i].parent_joint];
    EXPECT_EQ(joint.child_link, static_cast<int>(i));
    EXPECT_LT(joint.parent_link, static_cast<int>(i));
  }
  EXPECT_TRUE(warnings_.empty());
}

TEST_F(EveryJointTest, EveryJointTypeMatchesHandComputedPoses) {
  const double q_rev = 0.5, q_slide = 0.3, q_spin = -1.2;
  const std::vector<double> positions =
      ResolveJointPositions(robot_, {{"rev", q_rev}, {"slide", q_slide}, {"spin", q_spin}},
                            true, warnings_);
  const std::vector<Isometry3d> X_RL = ComputeLinkPoses(robot_, positions);

  // revolute: origin (1,0,0) yawed by pi/2, then q about z (the axis "0 0 2" is normalised)
  const double yaw = M_PI / 2 + q_rev;
  const Isometry3d X_Ra = Pose({1, 0, 0}, RotZ(yaw));
  ExpectPoseNear(X_Ra, PoseOf(X_RL, "a"));
  // prismatic: 1 up, then q along x of the rotated frame: (1 - 0.3 sin 0.5, 0.3 cos 0.5, 1)
  const Isometry3d X_Rb = Pose({1 - q_slide * std::sin(q_rev), q_slide * std::cos(q_rev), 1},
                               RotZ(yaw));
  ExpectPoseNear(X_Rb, PoseOf(X_RL, "b"));
  // continuous: origin with rpy (roll, pitch, yaw) = Rz(yaw) Ry(pitch) Rx(roll), diagonal axis
  const Matrix3d R_bJ = RotZ(-0.6) * RotY(0) * RotX(0.3);
  const Matrix3d R_Jc = AngleAxisd(q_spin, Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  const Isometry3d X_Rc = X_Rb * Pose({0.1, 0.2, 0.3}, R_bJ * R_Jc);
  ExpectPoseNear(X_Rc, PoseOf(X_RL, "c"));
  // fixed
  ExpectPoseNear(X_Rc * Pose({0, 0, 0.5}, RotY(0.25)), PoseOf(X_RL, "d"));
  // mimic: -0.5 * 0.5 + 0.1 = -0.15 about y
  ExpectPoseNear(Pose({0, 0, 0}, RotY(-0.15)), PoseOf(X_RL, "e"));
  // floating and planar joints stay at their origin
  ExpectPoseNear(Pose({0, 0, 2}, Matrix3d::Identity()), PoseOf(X_RL, "f"));
  ExpectPoseNear(Isometry3d::Identity(), PoseOf(X_RL, "g"));
  ExpectPoseNear(Isometry3d::Identity(), X_RL[0]);
}

TEST_F(EveryJointTest, AllocationFreeOverloadReusesTheVector) {
  std::vector<Isometry3d> X_RL(robot_.links().size());
  const Isometry3d* data = X_RL.data();
  std::vector<double> positions(robot_.joints().size(), 0.0);
  ComputeLinkPoses(robot_, positions, X_RL);
  EXPECT_EQ(X_RL.data(), data);
  ExpectPoseNear(Pose({1, 0, 0}, RotZ(M_PI / 2)), PoseOf(X_RL, "a"));
}

TEST_F(EveryJointTest, WrongNumberOfPositionsIsAnError) {
  try {
    ComputeLinkPoses(robot_, std::vector<double>(3, 0.0));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "ComputeLinkPoses: robot 'kinds' has 7 joints; 3 positions given");
  }
}

TEST(ForwardKinematicsTest, MrmAtAPoseMatchesClosedForm) {
  Warnings warnings;
  const Robot robot = LoadRobot(test::kMrmUrdf, "mrm.urdf", warnings);
  const double q1 = 0.3, q2 = 0.5, q3 = -0.4, q4 = 0.2, q5 = 1.0;
  const std::vector<double> positions = ResolveJointPositions(
      robot,
      {{"base_link__link_01", q1}, {"link_01__link_02", q2}, {"link_02__link_03", q3},
       {"link_03__link_04", q4}, {"link_04__link_05", q5}},
      true, warnings);
  const std::vector<Isometry3d> X_RL = ComputeLinkPoses(robot, positions);
  ASSERT_EQ(X_RL.size(), 6u);

  // the arm is planar in the plane yawed by q1: reach r and height z of link_05's origin
  const double r = 0.8 * (std::sin(q2) + std::sin(q2 + q3) + std::sin(q2 + q3 + q4));
  const double z = 0.9 + 0.8 * (std::cos(q2) + std::cos(q2 + q3) + std::cos(q2 + q3 + q4));
  const Isometry3d X_R5 =
      Pose({r * std::cos(q1), r * std::sin(q1), z}, RotZ(q1) * RotY(q2 + q3 + q4) * RotZ(q5));
  ExpectPoseNear(X_R5, X_RL[robot.FindLink("link_05")]);
  ExpectPoseNear(Pose({0, 0, 0.5}, RotZ(q1)), X_RL[robot.FindLink("link_01")]);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace urdfsnap::model
