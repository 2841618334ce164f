// Joint values: NAME=VALUE parsing, joint_state_publisher's defaults, clamping, mimic rules and
// the unknown-joint error.
#include "model/joint_values.h"

#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include "common/error.h"
#include "test_robots.h"

namespace urdfsnap::model {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Pair;

class ResolveTest : public ::testing::Test {
 protected:
  ResolveTest() : robot_(LoadRobot(test::kEveryJointUrdf, "kinds.urdf", load_warnings_)) {}

  double Position(const std::vector<double>& positions, const char* joint) const {
    return positions[robot_.FindJoint(joint)];
  }

  Warnings load_warnings_;
  Robot robot_;
  Warnings warnings_;
};

TEST_F(ResolveTest, DefaultsAreJointStatePublishers) {
  const std::vector<double> positions = ResolveJointPositions(robot_, {}, true, warnings_);
  EXPECT_EQ(Position(positions, "rev"), 0.0);
  EXPECT_DOUBLE_EQ(Position(positions, "slide"), 0.3);  // 0 is outside [0.1, 0.5]: the middle
  EXPECT_EQ(Position(positions, "spin"), 0.0);
  EXPECT_DOUBLE_EQ(Position(positions, "follower"), 0.1);  // -0.5 * 0 + 0.1
  EXPECT_THAT(warnings_.messages(),
              ElementsAre("joint 'free' is floating; urdfsnap draws it at its origin",
                          "joint 'plane' is planar; urdfsnap draws it at its origin"));
}

TEST_F(ResolveTest, OutOfLimitValuesAreClampedWithOneWarningEach) {
  const std::vector<double> positions = ResolveJointPositions(
      robot_, {{"rev", 2.5}, {"slide", -1}, {"spin", 7}}, true, warnings_);
  EXPECT_EQ(Position(positions, "rev"), 2.0);
  EXPECT_EQ(Position(positions, "slide"), 0.1);
  EXPECT_EQ(Position(positions, "spin"), 7.0);  // continuous: no limits
  EXPECT_DOUBLE_EQ(Position(positions, "follower"), -0.9);  // follows the clamped leader
  EXPECT_EQ(warnings_.messages()[0],
            "joint 'rev': 2.5 rad is outside its limits, -1 to 2 rad; clamped to 2 rad as "
            "joint_state_publisher's slider would (--no-clamp keeps it)");
  EXPECT_THAT(warnings_.messages()[1], HasSubstr("joint 'slide': -1 m is outside its limits, "));
  EXPECT_EQ(warnings_.messages().size(), 4u);  // and floating, planar
}

TEST_F(ResolveTest, NoClampKeepsValues) {
  const std::vector<double> positions =
      ResolveJointPositions(robot_, {{"rev", 2.5}}, false, warnings_);
  EXPECT_EQ(Position(positions, "rev"), 2.5);
  EXPECT_DOUBLE_EQ(Position(positions, "follower"), -1.15);
}

TEST_F(ResolveTest, AGivenMimicValueWinsWithAWarning) {
  const std::vector<double> positions =
      ResolveJointPositions(robot_, {{"rev", 1}, {"follower", 1.2}}, true, warnings_);
  EXPECT_EQ(Position(positions, "follower"), 1.2);
  EXPECT_EQ(warnings_.messages()[0],
            "joint 'follower' mimics joint 'rev'; the value given for it overrides the mimic rule");
}

TEST_F(ResolveTest, AValueForAFixedJointIsIgnored) {
  ResolveJointPositions(robot_, {{"weld", 1}}, true, warnings_);
  EXPECT_EQ(warnings_.messages()[0], "joint 'weld' is fixed; the value given for it is ignored");
}

TEST_F(ResolveTest, UnknownJointListsTheMovableJoints) {
  try {
    ResolveJointPositions(robot_, {{"elbow", 1}}, true, warnings_);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "robot 'kinds' has no joint 'elbow'; its movable joints are: rev, slide, spin");
  }
  try {
    ResolveJointPositions(robot_, {{"base", 1}}, true, warnings_);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("has no joint 'base' ('base' is a link)"));
  }
}

TEST(ParseJointAssignmentTest, NameEqualsValue) {
  NamedValues values;
  ParseJointAssignment("elbow=-1.5", values);
  ParseJointAssignment("wrist=+2e-1", values);
  EXPECT_THAT(values, ElementsAre(Pair("elbow", -1.5), Pair("wrist", 0.2)));
}

TEST(ParseJointAssignmentTest, BadAssignmentsAreErrors) {
  for (const char* text : {"elbow", "=1", "elbow=", "elbow=abc", "elbow=1.5rad", "elbow= 1",
                           "elbow=nan", "elbow=inf"}) {
    NamedValues values;
    try {
      ParseJointAssignment(text, values);
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("--joint '") + text +
                    "': expected NAME=VALUE with VALUE a number in radians or metres");
    }
  }
}

}  // namespace
}  // namespace urdfsnap::model
