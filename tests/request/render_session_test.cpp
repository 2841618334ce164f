// The render session: a request prepared once and drawn with per-frame changes as values (no file
// read again), each mesh and texture decoded once per process, the files a model read (for a live view's
// reload), forgetting models after an edit, caches that stay bounded over many models, and the
// outputs asked for (gl).
#include "request/render_session.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/gl_required.h"
#include "support/temp_folder.h"

namespace urdfsnap::request {
namespace {

namespace fs = std::filesystem;

// A triangle in the z = 0 plane facing +Z, `size` metres on a side.
std::string Stl(double size) {
  const std::string s = std::to_string(size);
  return "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex " + s + " 0 0\nvertex 0 " + s +
         " 0\nendloop\nendfacet\nendsolid t\n";
}

// A robot whose one link draws meshes/part.stl through a package:// URI, and a xacro that
// includes a property file.
void WriteRobot(const test::TempFolder& folder) {
  folder.Write("package.xml", "<package><name>demo_description</name></package>");
  folder.Write("meshes/part.stl", Stl(1));
  folder.Write("urdf/props.xacro",
               "<robot xmlns:xacro=\"http://www.ros.org/wiki/xacro\"><xacro:property name=\"s\" value=\"1\"/></robot>");
  folder.Write("urdf/robot.urdf.xacro",
               "<robot name=\"demo\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
               "<xacro:include filename=\"props.xacro\"/>\n"
               "<link name=\"base\"><visual><geometry><mesh filename=\"package://demo_description/meshes/"
               "part.stl\" scale=\"${s} ${s} ${s}\"/></geometry></visual></link>\n</robot>\n");
}

RenderRequest TopView(const std::string& model) {
  RenderRequest request;
  request.model.path = model;
  request.size = "64x48";
  request.pitch = "1.5";
  request.distance = "4";
  request.no_grid = true;
  return request;
}

int RobotPixels(const image::LabelImage& labels) {
  return static_cast<int>(std::count_if(labels.labels.begin(), labels.labels.end(), [](auto l) { return l != 0; }));
}

TEST(RenderSession, PreparesOnceThenDrawsPerFrameChangesWithoutReadingFiles) {
  URDFSNAP_REQUIRE_GL();
  const test::TempFolder folder("render_session_prepare");
  WriteRobot(folder);
  RenderSession session;
  Warnings warnings;
  RenderRequest request = TopView(folder.Path("urdf/robot.urdf.xacro"));
  request.yaw = "0.3";
  const Prepared first = session.Prepare(request, CommandLineLabel, warnings);
  ASSERT_NE(first.robot, nullptr);
  EXPECT_EQ(first.robot->links()[0].name, "base");
  EXPECT_EQ(first.positions.size(), first.robot->joints().size());
  EXPECT_DOUBLE_EQ(first.settings.view.yaw, 0.3);
  // the same request again: the same prepared robot, not a second one
  EXPECT_EQ(session.Prepare(request, CommandLineLabel, warnings).renderer, first.renderer);

  // with every file gone, frames are still drawn: a changed view is a value, not text to parse
  const image::Frame before = session.Draw(first, {false, false, true});
  fs::remove_all(folder.Path("meshes"));
  fs::remove_all(folder.Path("urdf"));
  Prepared turned = first;
  turned.settings.view.yaw += 0.5;
  const image::Frame after = session.Draw(turned, {false, false, true});
  EXPECT_GT(RobotPixels(after.labels), 10);
  EXPECT_NE(before.labels.labels, after.labels.labels);
}

TEST(RenderSession, DecodesEachMeshOncePerProcess) {
  URDFSNAP_REQUIRE_GL();
  const test::TempFolder folder("render_session_meshes");
  WriteRobot(folder);
  const RenderRequest request = TopView(folder.Path("urdf/robot.urdf.xacro"));
  Warnings warnings;
  // two sessions (as two commands of one process, or a session and a docs page) share the mesh
  RenderSession one, two;
  const Prepared a = one.Prepare(request, CommandLineLabel, warnings);
  const Prepared b = two.Prepare(request, CommandLineLabel, warnings);
  ASSERT_NE(a.renderer, b.renderer);
  const scene::Scene scene_a = a.renderer->Pose(a.positions);
  const scene::Scene scene_b = b.renderer->Pose(b.positions);
  ASSERT_EQ(scene_a.items.size(), 1u);
  ASSERT_EQ(scene_b.items.size(), 1u);
  EXPECT_EQ(scene_a.items[0].mesh.get(), scene_b.items[0].mesh.get());
}

TEST(RenderSession, DecodesEachTextureOncePerProcess) {
  URDFSNAP_REQUIRE_GL();
  // texbot: a URDF <texture> on its primitives and an OBJ whose material has a texture map
  const fs::path texbot = fs::path(URDFSNAP_SOURCE_DIR) / "tests/data/texbot_description";
  RenderRequest request = TopView((texbot / "urdf/texbot.urdf").string());
  request.model.packages["texbot_description"] = texbot.string();
  Warnings warnings;
  RenderSession one, two;
  const Prepared a = one.Prepare(request, CommandLineLabel, warnings);
  const Prepared b = two.Prepare(request, CommandLineLabel, warnings);
  ASSERT_NE(a.renderer, b.renderer);
  const scene::Scene scene_a = a.renderer->Pose(a.positions);
  const scene::Scene scene_b = b.renderer->Pose(b.positions);
  ASSERT_EQ(scene_a.items.size(), scene_b.items.size());
  int textured = 0;
  for (size_t i = 0; i < scene_a.items.size(); ++i) {
    if (!scene_a.items[i].texture) continue;
    ++textured;
    EXPECT_EQ(scene_a.items[i].texture.get(), scene_b.items[i].texture.get()) << "item " << i;
  }
  EXPECT_GE(textured, 4);
}

TEST(RenderSession, RenderReturnsTheRobotWithTheFrame) {
  URDFSNAP_REQUIRE_GL();
  const test::TempFolder folder("render_session_robot");
  WriteRobot(folder);
  RenderSession session;
  Warnings warnings;
  const Rendered rendered = session.Render(TopView(folder.Path("urdf/robot.urdf.xacro")), CommandLineLabel, warnings);
  ASSERT_NE(rendered.robot, nullptr);
  EXPECT_EQ(rendered.robot->name(), "demo");
  EXPECT_EQ(rendered.frame.colour.width, 64);
}

TEST(RenderSession, SaysWhichFilesAModelReadAndReadsThemAgainAfterForgetting) {
  URDFSNAP_REQUIRE_GL();
  const test::TempFolder folder("render_session");
  WriteRobot(folder);
  const std::string model = folder.Path("urdf/robot.urdf.xacro");
  RenderSession session;
  Warnings warnings;
  const RenderRequest request = TopView(model);
  const int before = RobotPixels(session.Render(request, CommandLineLabel, warnings, {false, false, true}).frame.labels);
  EXPECT_GT(before, 10);
  const std::vector<std::string> files = session.Files(request.model);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0], model);
  EXPECT_EQ(fs::canonical(files[1]), fs::canonical(folder.Path("urdf/props.xacro")));
  EXPECT_EQ(fs::canonical(files[2]), fs::canonical(folder.Path("meshes/part.stl")));

  // an edited mesh is drawn anew once the session forgets what it loaded
  folder.Write("meshes/part.stl", Stl(2));
  session.ForgetModels();
  EXPECT_TRUE(session.Files(request.model).empty());
  const int after = RobotPixels(session.Render(request, CommandLineLabel, warnings, {false, false, true}).frame.labels);
  EXPECT_GT(after, 3 * before);   // twice the size, four times the area
}

TEST(RenderSession, KeepsOnlyTheMostRecentlyUsedModels) {
  URDFSNAP_REQUIRE_GL();
  const test::TempFolder folder("render_session_lru");
  RenderSession session;
  Warnings warnings;
  std::vector<RenderRequest> requests;
  for (size_t k = 0; k <= RenderSession::kCachedModels; ++k) {
    const std::string name = "robot" + std::to_string(k) + ".urdf";
    folder.Write(name, "<robot name=\"r\"><link name=\"a\"><visual><geometry><box size=\"1 1 1\"/>"
                       "</geometry></visual></link></robot>");
    requests.push_back(TopView(folder.Path(name)));
    session.Render(requests.back(), CommandLineLabel, warnings);
  }
  // the first model was the least recently used when the ninth came
  EXPECT_TRUE(session.Files(requests[0].model).empty());
  for (size_t k = 1; k < requests.size(); ++k) EXPECT_EQ(session.Files(requests[k].model).size(), 1u) << k;
}

}  // namespace
}  // namespace urdfsnap::request
