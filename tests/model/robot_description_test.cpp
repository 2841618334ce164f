// DescribeRobot: the exact text `urdfsnap info` prints for a small robot.
#include "model/robot_description.h"

#include <gtest/gtest.h>

#include "test_robots.h"

namespace urdfsnap::model {
namespace {

TEST(RobotDescriptionTest, ListsLinksJointsAndTheTree) {
  Warnings warnings;
  const Robot robot = LoadRobot(test::kEveryJointUrdf, "kinds.urdf", warnings);
  EXPECT_EQ(DescribeRobot(robot),
            "robot 'kinds' from kinds.urdf: 8 links, 7 joints (3 movable)\n"
            "\n"
            "links:\n"
            "  base  0 visuals, 0 collisions\n"
            "  a     0 visuals, 0 collisions\n"
            "  b     0 visuals, 0 collisions\n"
            "  c     0 visuals, 0 collisions\n"
            "  d     0 visuals, 0 collisions\n"
            "  e     0 visuals, 0 collisions\n"
            "  f     0 visuals, 0 collisions\n"
            "  g     0 visuals, 0 collisions\n"
            "\n"
            "joints:\n"
            "  rev       revolute    base -> a  axis (0 0 1)  limits [-1, 2] rad\n"
            "  slide     prismatic   a -> b  axis (1 0 0)  limits [0.1, 0.5] m\n"
            "  spin      continuous  b -> c  axis (0 0.7071067811865476 0.7071067811865476)\n"
            "  weld      fixed       c -> d\n"
            "  follower  revolute    base -> e  axis (0 1 0)  limits [-2, 2] rad  mimic -0.5 * "
            "rev + 0.1\n"
            "  free      floating    base -> f\n"
            "  plane     planar      base -> g  axis (0 0 1)\n"
            "\n"
            "tree:\n"
            "  base\n"
            "    a  (rev, revolute)\n"
            "      b  (slide, prismatic)\n"
            "        c  (spin, continuous)\n"
            "          d  (weld, fixed)\n"
            "    e  (follower, revolute)\n"
            "    f  (free, floating)\n"
            "    g  (plane, planar)\n");
}

}  // namespace
}  // namespace urdfsnap::model
