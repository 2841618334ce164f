// Scene building with mesh files: errors and warnings point at the link in the model file, a
// missing mesh is skipped with --allow-missing-meshes, plain paths get one portability warning.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "common/error.h"
#include "model/forward_kinematics.h"
#include "scene/robot_scene.h"
#include "support/temp_folder.h"

namespace urdfsnap::scene {
namespace {

namespace fs = std::filesystem;

constexpr const char* kAsciiStl =
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
    "endloop\nendfacet\nendsolid t\n";

std::string MeshVisual(const std::string& uri) {
  return "<visual><origin xyz=\"0 0 1\"/><geometry><mesh filename=\"" + uri +
         "\" scale=\"2 3 -1\"/></geometry></visual>";
}

// Two links on lines 3 and 6 of the model, drawing the meshes `base_uri` and `arm_uri`.
std::string TwoMeshLinks(const std::string& base_uri, const std::string& arm_uri) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"m\">\n<link name=\"base\">\n" +
         MeshVisual(base_uri) + "\n</link>\n<link name=\"arm\">\n" + MeshVisual(arm_uri) +
         "\n</link>\n<joint name=\"j\" type=\"fixed\"><parent link=\"base\"/><child link=\"arm\"/>"
         "</joint>\n</robot>\n";
}

class SceneMeshTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_.emplace("scene_mesh_" +
                    std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    dir_ = folder_->path();
    fs::create_directories(dir_ / "meshes");
    std::ofstream(dir_ / "meshes/tri.stl") << kAsciiStl;
    options_.model_file = (dir_ / "robot.urdf").string();
  }
  void TearDown() override { folder_.reset(); }

  Scene Build(const std::string& uri) { return Build(uri, uri); }
  Scene Build(const std::string& base_uri, const std::string& arm_uri) {
    const model::Robot robot =
        model::LoadRobot(TwoMeshLinks(base_uri, arm_uri), options_.model_file, warnings_);
    return RobotScene(robot, options_, warnings_).Pose(model::ComputeLinkPoses(robot, {0.0}));
  }
  std::string ErrorOf(const std::string& base_uri, const std::string& arm_uri) {
    try {
      Build(base_uri, arm_uri);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  }
  std::string ErrorOf(const std::string& uri) { return ErrorOf(uri, uri); }
  size_t CountWarnings(const std::string& needle) const {
    return std::count_if(warnings_.messages().begin(), warnings_.messages().end(),
                         [&](const std::string& m) { return m.find(needle) != std::string::npos; });
  }

  std::optional<test::TempFolder> folder_;
  fs::path dir_;  // folder_'s path
  SceneOptions options_;
  Warnings warnings_;
};

TEST_F(SceneMeshTest, MissingMeshNamesModelLineLinkUriAndPlaceSearched) {
  const std::string error = ErrorOf("package://m_description/meshes/gone.stl");
  EXPECT_EQ(error.find(options_.model_file + ":3: link 'base': mesh "
                       "'package://m_description/meshes/gone.stl' not found"),
            0u)
      << error;
  EXPECT_NE(error.find("package 'm_description' not found, searched: "), std::string::npos)
      << error;
}

TEST_F(SceneMeshTest, AllowMissingMeshesDrawsTheRestWithOneWarningPerLink) {
  options_.allow_missing_meshes = true;
  const Scene scene = Build("meshes/gone.stl");
  EXPECT_TRUE(scene.items.empty());
  EXPECT_EQ(CountWarnings("--allow-missing-meshes"), 2u);
  EXPECT_EQ(CountWarnings(":6: link 'arm': mesh 'meshes/gone.stl' not found, searched: " +
                          (dir_ / "meshes/gone.stl").string()),
            1u);
}

TEST_F(SceneMeshTest, UnreadableMeshIsAnErrorEvenWhenMissingOnesAreAllowed) {
  std::ofstream(dir_ / "meshes/tri.stl", std::ios::trunc) << "this is not a mesh";
  options_.allow_missing_meshes = true;
  const std::string error = ErrorOf("meshes/tri.stl");
  EXPECT_EQ(error.find(options_.model_file + ":3: link 'base': "), 0u) << error;
}

TEST_F(SceneMeshTest, FilesLoadedInParallelStillReportTheFirstLinksError) {
  std::ofstream(dir_ / "meshes/a.stl") << "garbage a";
  std::ofstream(dir_ / "meshes/b.stl") << "garbage b";
  const std::string error = ErrorOf("meshes/a.stl", "meshes/b.stl");
  EXPECT_EQ(error.find(options_.model_file + ":3: link 'base': "), 0u) << error;
  EXPECT_NE(error.find("a.stl"), std::string::npos) << error;
}

TEST_F(SceneMeshTest, TwoFilesAreBothDrawn) {
  std::ofstream(dir_ / "meshes/other.stl") << kAsciiStl;
  EXPECT_EQ(Build("meshes/tri.stl", "meshes/other.stl").items.size(), 2u);
}

TEST_F(SceneMeshTest, MeshScaleAndOriginAreInThePose) {
  const Scene scene = Build("meshes/tri.stl");
  ASSERT_EQ(scene.items.size(), 2u);
  const Eigen::Affine3d& X_FG = scene.items[0].X_FG;
  EXPECT_TRUE(X_FG.linear().isApprox(Eigen::Vector3d(2, 3, -1).asDiagonal().toDenseMatrix()));
  EXPECT_TRUE(X_FG.translation().isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_LT(X_FG.linear().determinant(), 0);  // mirrored: the renderer flips its front faces
}

TEST_F(SceneMeshTest, PlainPathIsDrawnWithOnePortabilityWarning) {
  const Scene scene = Build("meshes/tri.stl");
  EXPECT_EQ(scene.items.size(), 2u);
  EXPECT_EQ(CountWarnings(options_.model_file +
                          ": mesh filenames without package:// or file:// are found by urdfsnap, "
                          "but not by RViz and other ROS tools"),
            1u);
}

TEST_F(SceneMeshTest, FileUriHasNoPortabilityWarning) {
  const Scene scene = Build("file://" + (dir_ / "meshes/tri.stl").string());
  EXPECT_EQ(scene.items.size(), 2u);
  EXPECT_TRUE(warnings_.empty());
}

}  // namespace
}  // namespace urdfsnap::scene
