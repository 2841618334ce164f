// ResolveMeshUri: package:// through --package and package.xml folders, file://, relative and
// absolute paths, and errors that name the URI and the places searched.
#include "geometry/mesh_uri.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "common/error.h"
#include "mesh_test_files.h"

namespace urdfsnap::geometry {
namespace {

using MeshUriTest = MeshFilesTest;

std::string ErrorOf(const std::string& uri, const std::string& model_file,
                    const std::map<std::string, std::string>& packages) {
  try {
    ResolveMeshUri(uri, model_file, packages);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(MeshUriTest, PackageUriThroughThePackageMap) {
  const std::string mesh =
      Write("somewhere/robot_description/meshes/base.stl", "solid x\nendsolid x\n");
  const std::map<std::string, std::string> packages{
      {"robot_description", (dir_ / "somewhere/robot_description").string()}};
  EXPECT_EQ(ResolveMeshUri("package://robot_description/meshes/base.stl", "", packages), mesh);
}

TEST_F(MeshUriTest, PackageUriThroughThePackageXmlAroundTheModelFile) {
  Write("ws/robot_description/package.xml", "<package><name>robot_description</name></package>");
  const std::string model = Write("ws/robot_description/urdf/robot.urdf", "<robot name=\"r\"/>");
  const std::string mesh = Write("ws/robot_description/meshes/arm.dae", "<COLLADA/>");
  EXPECT_EQ(ResolveMeshUri("package://robot_description/meshes/arm.dae", model, {}), mesh);
}

TEST_F(MeshUriTest, FileUriAbsoluteAndRelativePaths) {
  const std::string model = Write("robot/urdf/robot.urdf", "<robot name=\"r\"/>");
  const std::string mesh = Write("robot/meshes/base.stl", "solid x\nendsolid x\n");
  EXPECT_EQ(ResolveMeshUri("file://" + mesh, model, {}), mesh);
  EXPECT_EQ(ResolveMeshUri(mesh, model, {}), mesh);
  EXPECT_EQ(ResolveMeshUri("../meshes/base.stl", model, {}), mesh);
}

TEST_F(MeshUriTest, MissingFilesNameTheUriAndThePlacesSearched) {
  const std::string model = Write("robot/urdf/robot.urdf", "<robot name=\"r\"/>");
  const std::map<std::string, std::string> packages{{"robot", (dir_ / "robot").string()}};

  const std::string in_package = ErrorOf("package://robot/meshes/gone.stl", model, packages);
  EXPECT_EQ(in_package.find("mesh 'package://robot/meshes/gone.stl' not found"), 0u)
      << in_package;
  EXPECT_NE(in_package.find((dir_ / "robot/meshes/gone.stl").string()), std::string::npos)
      << in_package;

  const std::string no_package =
      ErrorOf("package://nowhere_description/meshes/a.stl", model, packages);
  EXPECT_NE(no_package.find("mesh 'package://nowhere_description/meshes/a.stl' not found"),
            std::string::npos)
      << no_package;
  EXPECT_NE(no_package.find("package 'nowhere_description' not found, searched: "),
            std::string::npos)
      << no_package;
  EXPECT_NE(no_package.find(model), std::string::npos) << no_package;

  const std::string relative = ErrorOf("meshes/gone.dae", model, {});
  EXPECT_NE(relative.find("mesh 'meshes/gone.dae' not found, searched: " +
                          (dir_ / "robot/urdf/meshes/gone.dae").string()),
            std::string::npos)
      << relative;

  EXPECT_NE(ErrorOf("file:///no/such/mesh.stl", model, {}).find("searched: /no/such/mesh.stl"),
            std::string::npos);
  EXPECT_NE(ErrorOf("http://example.com/a.stl", model, {}).find("unsupported URI scheme 'http://'"),
            std::string::npos);
  EXPECT_NE(ErrorOf("package://robot", model, packages).find("expected package://PACKAGE/PATH"),
            std::string::npos);
}

}  // namespace
}  // namespace urdfsnap::geometry
