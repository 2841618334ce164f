// The docs page model: table cells, the tree, which joints get sections, their pictures, moving
// links and sweeps (unit, no GL).
#include "docs/page_model.h"

#include <gtest/gtest.h>

#include <numbers>

#include "common/error.h"
#include "docs/fact_text.h"
#include "docs/file_names.h"
#include "docs/joint_sweeps.h"
#include "docs/test_robot.h"

namespace urdfsnap::docs {
namespace {

constexpr double kPi = std::numbers::pi;

struct PageModelTest : ::testing::Test {
  RobotPage Page(const PageOptions& options = {}) {
    return MakeRobotPage(robot, "/somewhere/urdf/grip.urdf", {{"arm", "left"}}, options, warnings);
  }
  Warnings warnings;
  model::Robot robot = model::LoadRobot(kGripperUrdf, "grip.urdf", warnings);
};

TEST_F(PageModelTest, JointRowsHaveTypesLimitsWithUnitsMimicAndDefaults) {
  const RobotPage page = Page();
  ASSERT_EQ(page.joints.size(), 6u);
  const JointRow& turn = page.joints[0];
  EXPECT_EQ(turn.type, "continuous");
  EXPECT_EQ(turn.parent + "/" + turn.child, "base/column");
  EXPECT_EQ(turn.axis, "(0, 0, 1)");
  EXPECT_EQ(turn.limits, "none (continuous)");
  EXPECT_EQ(turn.default_value, "0 rad (0°)");
  EXPECT_EQ(page.joints[1].limits, "-0.2 to 0.1 m");
  EXPECT_EQ(page.joints[1].default_value, "0 m");
  // 0 is outside [0.5, 1.5]: joint_state_publisher starts in the middle
  EXPECT_EQ(page.joints[2].limits, "0.5 to 1.5 rad (28.65° to 85.94°)");
  EXPECT_EQ(page.joints[2].default_value, "1 rad (57.3°)");
  EXPECT_EQ(page.joints[4].mimic, "-1 × finger_left + 0.1");
  EXPECT_EQ(page.joints[5].type, "fixed");
  EXPECT_EQ(page.joints[5].axis, "—");
  EXPECT_EQ(page.joints[5].limits, "—");
  EXPECT_EQ(page.joints[5].default_value, "—");
  // sections for the movable joints that are not mimics; the table links to them
  EXPECT_EQ(turn.anchor, "joint-turn");
  EXPECT_EQ(page.joints[4].anchor, "");
  EXPECT_EQ(page.joints[5].anchor, "");
}

TEST_F(PageModelTest, LinkRowsHaveShapesMeshesAndMass) {
  const RobotPage page = Page();
  ASSERT_EQ(page.links.size(), 7u);
  EXPECT_EQ(page.links[0].visual, "box 0.4 × 0.3 × 0.1 m");
  EXPECT_EQ(page.links[0].collision, "box 0.4 × 0.3 × 0.1 m");
  EXPECT_EQ(page.links[0].mass, "2.5 kg");
  EXPECT_EQ(page.links[1].visual, "cylinder r 0.05 m, length 0.5 m");
  EXPECT_EQ(page.links[1].collision, "—");
  EXPECT_EQ(page.links[1].mass, "—");
  EXPECT_EQ(page.links[2].visual, "mesh carriage.stl, scale 0.001");
  EXPECT_EQ(page.links[2].meshes, "package://grip/meshes/carriage.stl");
  EXPECT_EQ(page.links[3].visual, "sphere r 0.04 m");
}

TEST_F(PageModelTest, TreeFollowsTheLinksWithJointsAndDepths) {
  const RobotPage page = Page();
  ASSERT_EQ(page.tree.size(), 7u);
  EXPECT_EQ(page.tree[0].parent, -1);
  EXPECT_EQ(page.tree[0].joint, "");
  for (size_t i = 1; i < page.tree.size(); ++i) {
    const TreeNode& node = page.tree[i];
    ASSERT_GE(node.parent, 0);
    EXPECT_LT(node.parent, static_cast<int>(i)) << "parents come first";
    EXPECT_EQ(node.depth, page.tree[node.parent].depth + 1);
    EXPECT_EQ(node.link, robot.links()[i].name);
  }
  const int hand = robot.FindLink("hand");
  EXPECT_EQ(page.tree[hand].joint, "wrist");
  EXPECT_EQ(page.tree[hand].joint_type, "revolute");
  EXPECT_EQ(page.tree[hand].anchor, "joint-wrist");
  EXPECT_EQ(page.tree[hand].depth, 3);
}

TEST_F(PageModelTest, SourceNoteNamesTheFileArgumentsAndCounts) {
  const RobotPage page = Page();
  EXPECT_EQ(page.robot_name, "grip&bot");
  EXPECT_EQ(page.source_note,
            "From grip.urdf with xacro arguments arm:=left: 7 links, 6 joints (4 movable, 1 mimic). "
            "Made by urdfsnap docs; regenerate the page rather than edit it.");
}

TEST_F(PageModelTest, MimicJointsAreShownThroughTheirLeader) {
  const RobotPage page = Page();
  ASSERT_EQ(page.sections.size(), 4u);
  const JointSection& fingers = page.sections[3];
  EXPECT_EQ(fingers.name, "finger_left");
  EXPECT_NE(fingers.summary.find("Also moves its mimic joints: finger_right = -1 × finger_left + 0.1."),
            std::string::npos)
      << fingers.summary;
  // both fingers move, nothing else
  std::vector<std::string> moving;
  for (int link : fingers.moving_links) moving.push_back(robot.links()[link].name);
  EXPECT_EQ(moving, (std::vector<std::string>{"left", "a<b>|*_x_"}));
}

TEST_F(PageModelTest, AJointMovesItsWholeSubtree) {
  const RobotPage page = Page();
  std::vector<std::string> moving;
  for (int link : page.sections[1].moving_links) moving.push_back(robot.links()[link].name);
  EXPECT_EQ(moving, (std::vector<std::string>{"carriage", "hand", "left", "a<b>|*_x_"}));
}

TEST_F(PageModelTest, PicturesAtTheLimitsAndDefaultOrQuarterAndHalfTurns) {
  const RobotPage page = Page();
  const JointSection& turn = page.sections[0];
  ASSERT_EQ(turn.pictures.size(), 4u);
  EXPECT_EQ(turn.pictures[0].label, "quarter turn back");
  EXPECT_DOUBLE_EQ(turn.pictures[0].position, -kPi / 2);
  EXPECT_EQ(turn.pictures[0].value, "-1.5708 rad (-90°)");
  EXPECT_EQ(turn.pictures[0].file, "joints/turn/quarter-back.png");
  EXPECT_DOUBLE_EQ(turn.pictures[3].position, kPi);
  EXPECT_EQ(turn.pictures[3].file, "joints/turn/half-turn.png");

  const JointSection& wrist = page.sections[2];
  ASSERT_EQ(wrist.pictures.size(), 3u);
  EXPECT_EQ(wrist.pictures[0].label, "lower limit");
  EXPECT_DOUBLE_EQ(wrist.pictures[0].position, 0.5);
  EXPECT_EQ(wrist.pictures[1].label, "default");
  EXPECT_DOUBLE_EQ(wrist.pictures[1].position, 1.0);
  EXPECT_EQ(wrist.pictures[2].file, "joints/wrist/upper.png");
  EXPECT_EQ(wrist.pictures[2].alt, "wrist at upper limit, 1.5 rad (85.94°)");
  EXPECT_EQ(wrist.sweep_file, "joints/wrist/sweep.gif");
}

TEST_F(PageModelTest, SweepsLoopThroughTheRangeAtAnEvenSpeed) {
  const model::Joint& wrist = robot.joints()[2];
  const std::vector<double> sweep = SweepPositions(wrist, 1.0, 8);
  // default 1 → upper 1.5 → lower 0.5 → back to 1: length 2, a quarter per 2 frames
  const std::vector<double> expected = {1.0, 1.25, 1.5, 1.25, 1.0, 0.75, 0.5, 0.75};
  ASSERT_EQ(sweep.size(), expected.size());
  for (size_t k = 0; k < sweep.size(); ++k) EXPECT_NEAR(sweep[k], expected[k], 1e-12) << k;

  const std::vector<double> turn = SweepPositions(robot.joints()[0], 0, 4);
  EXPECT_NEAR(turn[1], kPi / 2, 1e-12);
  EXPECT_NEAR(turn[3], 3 * kPi / 2, 1e-12);
}

TEST_F(PageModelTest, JointPatternsChooseSectionsAndMimicPatternsTheirLeader) {
  PageOptions options;
  options.section_globs = {"finger_r*", "t?rn"};
  const RobotPage page = Page(options);
  ASSERT_EQ(page.sections.size(), 2u);
  EXPECT_EQ(page.sections[0].name, "turn");
  EXPECT_EQ(page.sections[1].name, "finger_left");
  EXPECT_NE(page.sections_note.find("2 movable joints are left out of this page (--sections)."), std::string::npos);
  EXPECT_EQ(page.joints[1].anchor, "");   // lift: no section, no link
}

TEST_F(PageModelTest, APatternMatchingNothingIsAnErrorListingTheJoints) {
  PageOptions options;
  options.section_globs = {"elbow*"};
  try {
    Page(options);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--sections 'elbow*' matches none of the movable joints of robot 'grip&bot': turn, lift, "
                           "wrist, finger_left");
  }
}

TEST_F(PageModelTest, NoAnimationsNoAnimationFiles) {
  PageOptions options;
  options.animation_extension = "";
  const RobotPage page = Page(options);
  EXPECT_EQ(page.turntable_file, "");
  for (const JointSection& section : page.sections) EXPECT_EQ(section.sweep_file, "");
  EXPECT_EQ(Views(page).size(), 2u);   // collision and TF
}

TEST(FileSafeNames, OddNamesBecomeSafeAndStayUnique) {
  EXPECT_EQ(FileSafeNames({"arm/joint 1", "Arm_joint_1", "arm_joint_1", "", ".hidden", "ünï", "a.b-c_D"}),
            (std::vector<std::string>{"arm_joint_1", "Arm_joint_1-2", "arm_joint_1-3", "_", "_hidden", "__n__",
                                      "a.b-c_D"}));
  EXPECT_EQ(FileSafeNames({std::string(100, 'x')})[0].size(), 60u);
}

TEST(FactText, NumbersAreShortAndLocaleFree) {
  EXPECT_EQ(ShortNumber(kPi / 4), "0.785398");
  EXPECT_EQ(ShortNumber(-0.0), "0");
  EXPECT_EQ(ShortNumber(1e-7), "1e-07");
  EXPECT_EQ(ShortNumber(90.0000001, 4), "90");
  EXPECT_EQ(ShortNumber(1234567), "1.23457e+06");
}

}  // namespace
}  // namespace urdfsnap::docs
