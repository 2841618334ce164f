// Scene building with textures: URDF <texture> materials on RViz's shapes (white, the link's
// default for collisions too), mesh texture maps and emission, materials with several texture
// maps, Ogre's warning texture, and missing texture files (unit).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/error.h"
#include "model/forward_kinematics.h"
#include "scene/primitive_meshes.h"
#include "scene/robot_scene.h"
#include "texture/texture_file.h"

namespace urdfsnap::scene {
namespace {

namespace fs = std::filesystem;

const fs::path kTexbot = fs::path(URDFSNAP_SOURCE_DIR) / "tests/data/texbot_description/urdf/texbot.urdf";

class SceneTextureTest : public ::testing::Test {
 protected:
  Scene Build(const std::string& urdf_text, const std::string& model_file = kTexbot.string()) {
    options_.model_file = model_file;
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
  std::shared_ptr<const texture::TextureImage> checker;
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
  // robot_link.cpp names the image to Ogre all the same, and Ogre draws its warning texture
  EXPECT_EQ(scene.items[0].texture, texture::WarningTexture());
  ASSERT_EQ(warnings_.messages().size(), 1u);
  EXPECT_NE(warnings_.messages()[0].find("drawn with Ogre's warning texture"), std::string::npos)
      << warnings_.messages()[0];
}

const fs::path kTextureMaps =
    fs::path(URDFSNAP_SOURCE_DIR) / "tests/data/texture_maps_description/urdf/texture_maps.urdf";

TEST_F(SceneTextureTest, EveryMapOfAMeshMaterialModulatesByItsDiffuseMap) {
  std::ostringstream text;
  text << std::ifstream(kTextureMaps).rdbuf();
  options_.packages = {{"texture_maps_description", kTextureMaps.parent_path().parent_path().string()}};
  const Scene scene = Build(text.str(), kTextureMaps.string());
  const auto item_of = [&](const std::string& link) {
    for (const DrawItem& item : scene.items) {
      if (item.link == robot_->FindLink(link)) return item;
    }
    ADD_FAILURE() << "no item of " << link;
    return DrawItem{};
  };
  EXPECT_FALSE(item_of("plain").texture);
  const DrawItem one = item_of("diffuse"), two = item_of("diffuse_bump"), three = item_of("diffuse_specular_bump");
  ASSERT_TRUE(one.texture);
  EXPECT_EQ(one.texture->width, 64);
  EXPECT_EQ(one.texture_units, 1);
  // the bump map's unit shows the diffuse map too: the same image, twice
  EXPECT_EQ(two.texture, one.texture);
  EXPECT_EQ(two.texture_units, 2);
  EXPECT_EQ(three.texture, one.texture);
  EXPECT_EQ(three.texture_units, 3);
  EXPECT_EQ(item_of("diffuse_bump_obj").texture_units, 2);
  EXPECT_EQ(item_of("base_colour_gltf").texture, one.texture);   // glTF: diffuse and base colour
  EXPECT_EQ(item_of("base_colour_gltf").texture_units, 2);
  // maps without a diffuse one: Ogre's warning texture over the material's own colour, said once
  const DrawItem bump_only = item_of("bump_only");
  EXPECT_EQ(bump_only.texture, texture::WarningTexture());
  EXPECT_EQ(bump_only.texture_units, 1);
  EXPECT_TRUE(bump_only.rgba.isApprox(Eigen::Vector4f(0.8f, 0.6f, 0.4f, 1)));
  ASSERT_EQ(warnings_.messages().size(), 1u);
  const std::string& warning = warnings_.messages()[0];
  EXPECT_NE(warning.find("link 'bump_only': mesh 'package://texture_maps_description/meshes/bump_only.dae'"),
            std::string::npos) << warning;
  EXPECT_NE(warning.find("no diffuse map"), std::string::npos) << warning;
}

TEST(WarningTextureTest, IsOgresYellowAndBlackStripes) {
  const std::shared_ptr<const texture::TextureImage> warning = texture::WarningTexture();
  ASSERT_EQ(warning->width, 8);
  ASSERT_EQ(warning->height, 8);
  ASSERT_EQ(warning->channels, 4);
  const auto texel = [&](int x, int y) {
    const std::uint8_t* t = &warning->texels[4 * (8 * y + x)];
    return std::array<int, 4>{t[0], t[1], t[2], t[3]};
  };
  // black where (x + y) mod 8 < 4, yellow elsewhere: diagonal stripes 4 texels wide
  const std::array<int, 4> black{0, 0, 0, 255}, yellow{255, 255, 0, 255};
  EXPECT_EQ(texel(0, 0), black);
  EXPECT_EQ(texel(3, 0), black);
  EXPECT_EQ(texel(4, 0), yellow);
  EXPECT_EQ(texel(7, 0), yellow);
  EXPECT_EQ(texel(7, 1), black);
  EXPECT_EQ(texel(2, 5), yellow);
  EXPECT_EQ(texture::WarningTexture(), warning);
}

}  // namespace
}  // namespace urdfsnap::scene
