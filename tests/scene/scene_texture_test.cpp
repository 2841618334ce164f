// Scene building with textures: URDF <texture> materials on RViz's shapes (white, the link's
// default for collisions too), mesh texture maps and emission, and missing texture files (unit).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "model/forward_kinematics.h"
#include "scene/primitive_meshes.h"
#include "scene/robot_scene.h"

namespace urdfsnap::scene {
namespace {

namespace fs = std::filesystem;

const fs::path kTexbot = fs::path(URDFSNAP_SOURCE_DIR) / "tests/data/texbot_description/urdf/texbot.urdf";

class SceneTextureTest : public ::testing::Test {
 protected:
  Scene Build(const std::string& urdf_text) {
    options_.model_file = kTexbot.string();
    robot_.emplace(model::LoadRobot(urdf_text, options_.model_file, warnings_));
    return RobotScene(*robot_, options_, warnings_)
        .Pose(model::ComputeLinkPoses(*robot_, std::vector<double>(robot_->joints().size(), 0.0)));
  }
  Scene BuildTexbot() {
    std::ostringstream text;
    text << std::ifstream(kTexbot).rdbuf();
    return Build(text.str());
  }
  SceneOptions options_;
  Warnings warnings_;
  std::optional<model::Robot> robot_;   // the last one built
};

TEST_F(SceneTextureTest, UrdfTextureIsDrawnOnWhiteOnEveryShapeAndCollision) {
  options_.show_collision = true;
  const Scene scene = BuildTexbot();
  EXPECT_TRUE(warnings_.empty());
  int textured_shapes = 0;
  std::shared_ptr<const TextureImage> checker;
  for (const DrawItem& item : scene.items) {
    if (item.mesh != UnitBoxMesh() && item.mesh != UnitCylinderMesh() && item.mesh != UnitSphereMesh()) continue;
    ASSERT_TRUE(item.texture) << item.link;
    // getMaterialForLink sets no colour on a textured material: Ogre's white stays
    EXPECT_TRUE(item.rgba.isApprox(Eigen::Vector4f::Ones()));
    if (!checker) checker = item.texture;
    EXPECT_EQ(item.texture, checker);   // one texture, loaded once
    ++textured_shapes;
  }
  // base visual and collision, drum, ball
  EXPECT_EQ(textured_shapes, 4);
  ASSERT_TRUE(checker);
  EXPECT_EQ(checker->width, 64);
  EXPECT_EQ(checker->channels, 4);
}

TEST_F(SceneTextureTest, MeshMaterialsKeepTheirTextureAndEmission) {
  const Scene scene = BuildTexbot();
  int lamp_parts = 0, textured = 0, glowing = 0;
  for (const DrawItem& item : scene.items) {
    if (item.link != robot_->FindLink("lamp")) continue;
    ++lamp_parts;
    textured += item.texture != nullptr;
    glowing += item.emissive.isApprox(Eigen::Vector3f(0, 0.6f, 0.2f));
  }
  EXPECT_EQ(lamp_parts, 2);
  EXPECT_EQ(textured, 1);
  EXPECT_EQ(glowing, 1);
}

constexpr const char* kMissingTexture = R"(<robot name="r">
  <link name="plate">
    <visual><geometry><box size="1 1 1"/></geometry>
      <material name="m"><texture filename="package://texbot_description/textures/none.png"/></material>
    </visual>
  </link>
</robot>)";

TEST_F(SceneTextureTest, MissingTextureIsAnErrorAtTheLinkOrAWarningWhenAllowed) {
  try {
    Build(kMissingTexture);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(kTexbot.string() + ":2: link 'plate': "), std::string::npos) << what;
    EXPECT_NE(what.find("none.png"), std::string::npos) << what;
  }
  options_.allow_missing_meshes = true;
  const Scene scene = Build(kMissingTexture);
  ASSERT_EQ(scene.items.size(), 1u);
  EXPECT_FALSE(scene.items[0].texture);
  ASSERT_EQ(warnings_.messages().size(), 1u);
  EXPECT_NE(warnings_.messages()[0].find("drawn without it"), std::string::npos) << warnings_.messages()[0];
}

}  // namespace
}  // namespace urdfsnap::scene
