// LoadRobot: the model it builds from URDF text, and an error with file:line naming the culprit
// for each kind of bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "model/robot.h"
#include "test_names.h"
#include "test_robots.h"

namespace urdfsnap::model {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(UrdfLoaderTest, LoadsTheMrmRobot) {
  Warnings warnings;
  const Robot robot = LoadRobot(test::kMrmUrdf, "mrm.urdf", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(robot.name(), "mrm");
  EXPECT_EQ(robot.source(), "mrm.urdf");
  ASSERT_EQ(robot.links().size(), 6u);
  ASSERT_EQ(robot.joints().size(), 5u);
  EXPECT_EQ(robot.links()[0].name, "base_link");
  EXPECT_EQ(robot.links()[0].line, 3);
  EXPECT_EQ(robot.links()[0].parent_joint, -1);
  ASSERT_EQ(robot.links()[0].visuals.size(), 1u);
  EXPECT_EQ(robot.links()[0].visuals[0].shape.type, Shape::Type::kBox);

  const Joint& shoulder = robot.joints()[robot.FindJoint("link_01__link_02")];
  EXPECT_EQ(shoulder.type, JointType::kRevolute);
  EXPECT_EQ(shoulder.line, 19);
  EXPECT_EQ(robot.links()[shoulder.parent_link].name, "link_01");
  EXPECT_EQ(robot.links()[shoulder.child_link].name, "link_02");
  EXPECT_TRUE(shoulder.axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(shoulder.X_PJ.translation().isApprox(Eigen::Vector3d(0, 0, 0.4)));
  EXPECT_TRUE(shoulder.has_limits);
  EXPECT_EQ(shoulder.lower, -3.14);
  EXPECT_EQ(shoulder.upper, 3.14);
  EXPECT_EQ(shoulder.mimic_leader, -1);
  EXPECT_THAT(robot.MovableJointNames(),
              ElementsAre("base_link__link_01", "link_01__link_02", "link_02__link_03",
                          "link_03__link_04", "link_04__link_05"));
  EXPECT_EQ(robot.FindLink("nope"), -1);
  EXPECT_EQ(robot.FindJoint("nope"), -1);
}

TEST(UrdfLoaderTest, MimicJointsPointAtTheirLeader) {
  Warnings warnings;
  const Robot robot = LoadRobot(test::kEveryJointUrdf, "kinds.urdf", warnings);
  const Joint& follower = robot.joints()[robot.FindJoint("follower")];
  EXPECT_EQ(follower.mimic_leader, robot.FindJoint("rev"));
  EXPECT_EQ(follower.mimic_multiplier, -0.5);
  EXPECT_EQ(follower.mimic_offset, 0.1);
  EXPECT_THAT(robot.MovableJointNames(), ElementsAre("rev", "slide", "spin"));
  EXPECT_EQ(robot.joints()[robot.FindJoint("weld")].type, JointType::kFixed);
  EXPECT_EQ(robot.joints()[robot.FindJoint("free")].type, JointType::kFloating);
  EXPECT_EQ(robot.joints()[robot.FindJoint("plane")].type, JointType::kPlanar);
  EXPECT_EQ(robot.joints()[robot.FindJoint("spin")].type, JointType::kContinuous);
  EXPECT_EQ(robot.joints()[robot.FindJoint("slide")].type, JointType::kPrismatic);
}

TEST(UrdfLoaderTest, AnAxisWithoutXyzIsUrdfsDefaultX) {
  Warnings warnings;
  const Robot robot = LoadRobot(
      R"(<robot name="r"><link name="a"/><link name="b"/>
           <joint name="j" type="continuous"><parent link="a"/><child link="b"/><axis/></joint>
         </robot>)",
      "axis.urdf", warnings);
  EXPECT_EQ(robot.joints()[0].axis, Eigen::Vector3d::UnitX());
  EXPECT_TRUE(warnings.empty());
}

struct BadUrdfCase {
  const char* what;
  const char* urdf;
  const char* message;  // the whole message after "bad.urdf:"
};

// Two links joined by `joint`, which starts on line 4.
#define TWO_LINKS(joint) \
  "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n" joint "\n</robot>\n"

const BadUrdfCase kBadUrdfCases[] = {
    {"malformed XML", "<robot name=\"r\">\n<link name=\"a\">\n</robot>\n",
     "2: malformed XML (XML_ERROR_MISMATCHED_ELEMENT): XMLElement name=link"},
    {"not a robot", "<model/>\n", "1: expected a <robot> root element, found <model>"},
    {"no links", "<robot name=\"r\">\n</robot>\n", "1: robot 'r' has no <link>"},
    {"duplicate link", "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"a\"/>\n</robot>\n",
     "3: link 'a' is defined twice (first at line 2)"},
    {"duplicate joint",
     TWO_LINKS("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
               "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"),
     "5: joint 'j' is defined twice (first at line 4)"},
    {"missing child link",
     TWO_LINKS("<joint name=\"j\" type=\"fixed\">\n<parent link=\"a\"/>\n<child link=\"c\"/>\n"
               "</joint>"),
     "6: joint 'j' names child link 'c', which is not defined"},
    {"no parent",
     TWO_LINKS("<joint name=\"j\" type=\"fixed\">\n<child link=\"b\"/>\n</joint>"),
     "4: joint 'j' has no <parent link=...>"},
    {"unknown type",
     TWO_LINKS("<joint name=\"j\" type=\"hinge\"><parent link=\"a\"/><child link=\"b\"/></joint>"),
     "4: joint 'j' has unknown type 'hinge'; expected revolute, continuous, prismatic, fixed, "
     "floating or planar"},
    {"missing limit",
     TWO_LINKS("<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
               "</joint>"),
     "4: joint 'j' is revolute but has no <limit>"},
    {"limit without effort",
     TWO_LINKS("<joint name=\"j\" type=\"prismatic\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<limit lower=\"0\" upper=\"1\" velocity=\"1\"/></joint>"),
     "5: joint 'j': <limit> has no effort attribute"},
    {"lower above upper",
     TWO_LINKS("<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/></joint>"),
     "5: joint 'j': lower limit 1 is above upper limit -1"},
    {"lower above a missing upper",
     TWO_LINKS("<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<limit lower=\"0.5\" effort=\"1\" velocity=\"1\"/></joint>"),
     "5: joint 'j': lower limit 0.5 is above upper limit 0"},
    {"unparsable origin",
     TWO_LINKS("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<origin xyz=\"0 0 x\"/></joint>"),
     "5: joint 'j': <origin xyz=\"0 0 x\">: expected 3 finite numbers"},
    {"nan in an origin",
     TWO_LINKS("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<origin rpy=\"0 nan 0\"/></joint>"),
     "5: joint 'j': <origin rpy=\"0 nan 0\">: expected 3 finite numbers"},
    {"infinite limit",
     TWO_LINKS("<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<limit lower=\"-inf\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"),
     "5: joint 'j': <limit lower=\"-inf\">: expected 1 finite number"},
    {"number out of double range",
     TWO_LINKS("<joint name=\"j\" type=\"prismatic\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<limit upper=\"1e999\" effort=\"1\" velocity=\"1\"/></joint>"),
     "5: joint 'j': <limit upper=\"1e999\">: expected 1 finite number"},
    {"two signs",
     TWO_LINKS("<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<origin xyz=\"+-1 0 0\"/></joint>"),
     "5: joint 'j': <origin xyz=\"+-1 0 0\">: expected 3 finite numbers"},
    {"bare ampersand in a name (found by fuzzing)",
     TWO_LINKS("<joint name=\"j&\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>"),
     "4: joint 'j&': urdfdom reads this name differently (characters such as a bare '&' must be "
     "escaped)"},
    {"zero box side",
     "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>\n<box size=\"1 0 1\"/>\n"
     "</geometry></visual>\n</link>\n</robot>\n",
     "4: link 'a': <box size=\"1 0 1\">: expected sizes above 0"},
    {"negative cylinder radius",
     "<robot name=\"r\">\n<link name=\"a\">\n<collision><geometry>\n"
     "<cylinder radius=\"-0.1\" length=\"1\"/>\n</geometry></collision>\n</link>\n</robot>\n",
     "4: link 'a': <cylinder radius=\"-0.1\">: expected a size above 0"},
    {"zero cylinder length",
     "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>\n"
     "<cylinder radius=\"0.1\" length=\"0\"/>\n</geometry></visual>\n</link>\n</robot>\n",
     "4: link 'a': <cylinder length=\"0\">: expected a size above 0"},
    {"zero sphere radius",
     "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>\n<sphere radius=\"0\"/>\n"
     "</geometry></visual>\n</link>\n</robot>\n",
     "4: link 'a': <sphere radius=\"0\">: expected a size above 0"},
    {"zero mesh scale",
     "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>\n"
     "<mesh filename=\"m.stl\" scale=\"1 1 0\"/>\n</geometry></visual>\n</link>\n</robot>\n",
     "4: link 'a': <mesh scale=\"1 1 0\">: a scale of 0 flattens the mesh to nothing"},
    {"two numbers for a box",
     "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>\n<box size=\"1 1\"/>\n"
     "</geometry></visual>\n</link>\n</robot>\n",
     "4: link 'a': <box size=\"1 1\">: expected 3 finite numbers"},
    {"unknown geometry",
     "<robot name=\"r\">\n<link name=\"a\">\n<visual><geometry>\n<cone radius=\"1\"/>\n"
     "</geometry></visual>\n</link>\n</robot>\n",
     "4: link 'a': <geometry> needs one of box, cylinder, sphere or mesh, found <cone>"},
    {"zero axis",
     TWO_LINKS("<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<axis xyz=\"0 0 0\"/></joint>"),
     "5: joint 'j' has a zero axis"},
    {"several roots", "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n</robot>\n",
     "3: robot 'r' has several root links (links without a parent joint): 'a' (line 2), "
     "'b' (line 3); a URDF tree has exactly one"},
    {"two parents",
     "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n<link name=\"c\"/>\n"
     "<joint name=\"j1\" type=\"fixed\"><parent link=\"a\"/><child link=\"c\"/></joint>\n"
     "<joint name=\"j2\" type=\"fixed\"><parent link=\"b\"/><child link=\"c\"/></joint>\n"
     "</robot>\n",
     "6: link 'c' is the child of two joints: 'j1' (line 5) and 'j2'"},
    {"loop",
     "<robot name=\"r\">\n<link name=\"root\"/>\n<link name=\"a\"/>\n<link name=\"b\"/>\n"
     "<joint name=\"j1\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
     "<joint name=\"j2\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint>\n"
     "</robot>\n",
     "5: joint 'j1' closes a loop of links 'b' -> 'a' -> 'b' (parent to child); a URDF must be "
     "a tree"},
    {"mimic of an unknown joint",
     TWO_LINKS("<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>\n"
               "<mimic joint=\"ghost\"/></joint>"),
     "5: joint 'j' mimics joint 'ghost', which is not defined"},
    {"circle of mimic joints",
     "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n<link name=\"c\"/>\n"
     "<joint name=\"j1\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>\n"
     "<mimic joint=\"j2\"/></joint>\n"
     "<joint name=\"j2\" type=\"continuous\"><parent link=\"a\"/><child link=\"c\"/>\n"
     "<mimic joint=\"j1\"/></joint>\n</robot>\n",
     "6: joint 'j1' mimics itself through a circle of mimic joints: 'j1' -> 'j2' -> 'j1'"},
    {"circle of mimic joints behind a mimicking joint",
     "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n<link name=\"c\"/>\n"
     "<link name=\"d\"/>\n"
     "<joint name=\"j0\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/>\n"
     "<mimic joint=\"j2\"/></joint>\n"
     "<joint name=\"j1\" type=\"continuous\"><parent link=\"a\"/><child link=\"c\"/>\n"
     "<mimic joint=\"j3\"/></joint>\n"
     "<joint name=\"j2\" type=\"continuous\"><parent link=\"a\"/><child link=\"d\"/>\n"
     "<mimic joint=\"j1\"/></joint>\n"
     "<joint name=\"j3\" type=\"continuous\"><parent link=\"b\"/><child link=\"e\"/>\n"
     "<mimic joint=\"j2\"/></joint>\n<link name=\"e\"/>\n</robot>\n",
     "9: joint 'j1' mimics itself through a circle of mimic joints: 'j1' -> 'j3' -> 'j2' -> 'j1'"},
};

class BadUrdfTest : public ::testing::TestWithParam<BadUrdfCase> {};

TEST_P(BadUrdfTest, ErrorNamesFileLineAndCulprit) {
  Warnings warnings;
  try {
    LoadRobot(GetParam().urdf, "bad.urdf", warnings);
    FAIL() << "no error for " << GetParam().what;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), std::string("bad.urdf:") + GetParam().message);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadUrdfTest, ::testing::ValuesIn(kBadUrdfCases),
                         [](const ::testing::TestParamInfo<BadUrdfCase>& info) {
                           return test::TestName(info.param.what);
                         });

// A 5,000-link chain whose joints each mimic the one before: the tree and mimic checks walk
// each link and joint once (they were cubic in the chain's length, minutes for this robot).
TEST(UrdfLoaderTest, DeepChainsOfLinksAndMimicJointsLoad) {
  const int n = 5000;
  std::string urdf = "<robot name=\"deep\">\n<link name=\"l0\"/>\n";
  for (int i = 1; i < n; ++i) {
    const std::string k = std::to_string(i), parent = std::to_string(i - 1);
    urdf += "<link name=\"l" + k + "\"/><joint name=\"j" + k +
            "\" type=\"continuous\"><parent link=\"l" + parent + "\"/><child link=\"l" + k + "\"/>" +
            (i > 1 ? "<mimic joint=\"j" + parent + "\"/>" : "") + "</joint>\n";
  }
  urdf += "</robot>\n";
  Warnings warnings;
  const Robot robot = LoadRobot(urdf, "deep.urdf", warnings);
  EXPECT_EQ(robot.links().size(), static_cast<size_t>(n));
  EXPECT_EQ(robot.MovableJointNames().size(), 1u);  // the others mimic it
}

}  // namespace
}  // namespace urdfsnap::model
