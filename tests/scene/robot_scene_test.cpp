// A robot's scene, prepared once and posed: shapes, sizes, colours, link indices, frames and display
// switches (unit).
#include "scene/robot_scene.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "model/forward_kinematics.h"
#include "scene/primitive_meshes.h"

namespace urdfsnap::scene {
namespace {

constexpr const char* kTwoLinks = R"(<?xml version="1.0"?>
<robot name="two">
  <material name="blue"><color rgba="0 0 1 1"/></material>
  <link name="base">
    <visual><origin xyz="0 0 0.5"/><geometry><box size="1 2 3"/></geometry></visual>
    <collision><geometry><sphere radius="0.25"/></geometry></collision>
  </link>
  <joint name="lift" type="prismatic">
    <parent link="base"/><child link="arm"/>
    <origin xyz="0 0 1"/><axis xyz="0 0 1"/>
    <limit lower="0" upper="2" effort="1" velocity="1"/>
  </joint>
  <link name="arm">
    <visual><geometry><cylinder radius="0.1" length="0.8"/></geometry>
      <material name="blue"/></visual>
  </link>
</robot>)";

struct RobotSceneTest : ::testing::Test {
  Scene Build(const SceneOptions& options, double lift = 0.5) {
    const model::Robot robot = model::LoadRobot(kTwoLinks, "two.urdf", warnings);
    const std::vector<double> positions = {lift};
    return RobotScene(robot, options, warnings).Pose(model::ComputeLinkPoses(robot, positions));
  }
  Warnings warnings;
};

TEST_F(RobotSceneTest, VisualsGetRvizShapesSizesAndColours) {
  const Scene scene = Build({});
  ASSERT_EQ(scene.items.size(), 2u);
  const DrawItem& box = scene.items[0];
  EXPECT_EQ(box.mesh, UnitBoxMesh());
  EXPECT_EQ(box.link, 0);
  EXPECT_TRUE(box.rgba.isApprox(Eigen::Vector4f(1, 0, 0, 1)));  // no material: RViz red
  EXPECT_TRUE(box.X_FG.linear().isApprox(Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix()));
  EXPECT_TRUE(box.X_FG.translation().isApprox(Eigen::Vector3d(0, 0, 0.5)));

  const DrawItem& arm = scene.items[1];
  EXPECT_EQ(arm.mesh, UnitCylinderMesh());
  EXPECT_TRUE(arm.rgba.isApprox(Eigen::Vector4f(0, 0, 1, 1)));
  EXPECT_TRUE(arm.X_FG.linear().isApprox(Eigen::Vector3d(0.2, 0.2, 0.8).asDiagonal().toDenseMatrix()));
  EXPECT_TRUE(arm.X_FG.translation().isApprox(Eigen::Vector3d(0, 0, 1.5)));
  EXPECT_TRUE(warnings.empty());
}

TEST_F(RobotSceneTest, FixedFrameMovesEverythingIntoThatLink) {
  SceneOptions options;
  options.fixed_frame = "arm";
  const Scene scene = Build(options);
  EXPECT_TRUE(scene.items[1].X_FG.translation().isZero(1e-12));
  EXPECT_TRUE(scene.items[0].X_FG.translation().isApprox(Eigen::Vector3d(0, 0, -1.0)));
}

TEST_F(RobotSceneTest, UnknownFixedFrameNamesTheLinks) {
  SceneOptions options;
  options.fixed_frame = "world";
  try {
    Build(options);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "fixed frame 'world' is not a link of robot 'two' (links: base, arm)");
  }
}

TEST_F(RobotSceneTest, CollisionOnlyUsesTheVisualColourElseRed) {
  SceneOptions options;
  options.show_visual = false;
  options.show_collision = true;
  const Scene scene = Build(options);
  ASSERT_EQ(scene.items.size(), 1u);
  EXPECT_EQ(scene.items[0].mesh, UnitSphereMesh());
  EXPECT_TRUE(scene.items[0].rgba.isApprox(Eigen::Vector4f(1, 0, 0, 1)));
  EXPECT_TRUE(scene.items[0].X_FG.linear().isApprox(Eigen::Matrix3d::Identity() * 0.5));
}

TEST_F(RobotSceneTest, RobotAlphaMultipliesMaterialAlpha) {
  SceneOptions options;
  options.alpha = 0.5;
  const Scene scene = Build(options);
  EXPECT_FLOAT_EQ(scene.items[1].rgba.w(), 0.5f);
}

TEST_F(RobotSceneTest, LinkAlphaMultipliesThatLinksAlphaOnly) {
  // RViz: robot alpha * material alpha * link alpha (robot_link.cpp updateAlpha)
  SceneOptions options;
  options.alpha = 0.5;
  options.link_alpha = {{"base", 0.25}};
  options.show_collision = true;
  const Scene scene = Build(options);
  ASSERT_EQ(scene.items.size(), 3u);   // base visual, base collision, arm visual
  EXPECT_EQ(scene.items[0].link, 0);
  EXPECT_FLOAT_EQ(scene.items[0].rgba.w(), 0.125f);
  EXPECT_FLOAT_EQ(scene.items[1].rgba.w(), 0.125f);   // collision shapes too
  EXPECT_EQ(scene.items[2].link, 1);
  EXPECT_FLOAT_EQ(scene.items[2].rgba.w(), 0.5f);
  EXPECT_TRUE(scene.items[2].rgba.head<3>().isApprox(Eigen::Vector3f(0, 0, 1)));   // colour kept
}

TEST_F(RobotSceneTest, LinkAlphaForAnUnknownLinkOrOutOfRangeIsAnError) {
  SceneOptions options;
  options.link_alpha = {{"elbow", 0.5}};
  try {
    Build(options);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "link alpha for 'elbow', which is not a link of robot 'two' (links: base, arm)");
  }
  options.link_alpha = {{"arm", 1.5}};
  try {
    Build(options);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "link alpha for 'arm' is 1.5; expected 0 to 1");
  }
}

TEST_F(RobotSceneTest, GridIsElevenPlusElevenLinesOverTenMetres) {
  const Scene scene = Build({});
  ASSERT_EQ(scene.lines.size(), 1u);
  const LineSet& grid = scene.lines[0];
  EXPECT_EQ(grid.points.size(), 44u);
  for (const auto& p : grid.points) {
    EXPECT_LE(p.cwiseAbs().maxCoeff(), 5.0f);
    EXPECT_EQ(p.z(), 0.0f);
  }
  EXPECT_TRUE(grid.rgba.isApprox(Eigen::Vector4f(160 / 255.f, 160 / 255.f, 164 / 255.f, 0.5f)));
  SceneOptions no_grid;
  no_grid.grid.enabled = false;
  EXPECT_TRUE(Build(no_grid).lines.empty());
}

TEST_F(RobotSceneTest, TfDisplayGivesAxesArrowsAndANameAtEachFrame) {
  SceneOptions options;
  options.show_visual = false;
  options.tf.enabled = true;
  const Scene scene = Build(options, 0.5);
  // three axes per frame, and a shaft and head from arm to its parent
  EXPECT_EQ(scene.items.size(), 3u * 2 + 2);
  ASSERT_EQ(scene.labels.size(), 2u);
  EXPECT_TRUE(scene.labels[0].anchor.isZero());
  EXPECT_TRUE(scene.labels[1].anchor.isApprox(Eigen::Vector3d(0, 0, 1.5)));
  for (const auto& label : scene.labels) {
    ASSERT_FALSE(label.quads.empty());
    EXPECT_TRUE(label.rgba.isApprox(Eigen::Vector4f::Ones()));   // white
    EXPECT_FLOAT_EQ(label.quads[0].min.y(), -0.1f);              // 0.1 m, below the origin
  }
  EXPECT_EQ(scene.labels[0].quads.size(), 4u);   // "base"

  options.tf.marker_scale = 2;
  EXPECT_FLOAT_EQ(Build(options).labels[0].quads[0].min.y(), -0.2f);
  options.tf.show_names = false;
  options.tf.show_axes = false;
  const Scene arrows_only = Build(options);
  EXPECT_TRUE(arrows_only.labels.empty());
  EXPECT_EQ(arrows_only.items.size(), 2u);
}

}  // namespace
}  // namespace urdfsnap::scene
