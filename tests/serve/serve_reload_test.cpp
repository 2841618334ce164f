// A model edited, broken and fixed while the server runs: the next frame and /api/robot show the
// edit, a broken edit answers the located error `render` prints, and the next good edit recovers.
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/urdfsnap_process.h"
#include "serve_process.h"
#include "support/gl_required.h"
#include "support/temp_folder.h"

namespace urdfsnap::serve_test {
namespace {

// a xacro robot whose limit and size live in an included file
constexpr const char* kRobot = R"(<?xml version="1.0"?>
<robot name="lamp" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="params.xacro"/>
  <link name="base"><visual><geometry><box size="0.4 0.4 0.1"/></geometry></visual></link>
  <link name="arm"><visual><origin xyz="0 0 0.3"/><geometry><box size="0.1 0.1 ${arm_length}"/></geometry></visual></link>
  <link name="head"><visual><geometry><mesh filename="head.stl"/></geometry></visual></link>
  <joint name="tilt" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="${tilt_upper}" effort="1" velocity="1"/></joint>
  <joint name="fix" type="fixed"><parent link="arm"/><child link="head"/><origin xyz="0 0 0.6"/></joint>
</robot>
)";

std::string Params(double upper, double length) {
  return "<robot xmlns:xacro='http://www.ros.org/wiki/xacro'>\n  <xacro:property name='tilt_upper' value='" +
         std::to_string(upper) + "'/>\n  <xacro:property name='arm_length' value='" + std::to_string(length) +
         "'/>\n</robot>\n";
}

// An ASCII STL tetrahedron of the given size.
std::string Tetrahedron(double s) {
  const std::string a = "0 0 0", b = std::to_string(s) + " 0 0", c = "0 " + std::to_string(s) + " 0",
                    d = "0 0 " + std::to_string(s);
  std::string stl = "solid t\n";
  for (const auto& [p, q, r] : {std::tuple{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}}) {
    stl += "facet normal 0 0 0\nouter loop\nvertex " + p + "\nvertex " + q + "\nvertex " + r + "\nendloop\nendfacet\n";
  }
  return stl + "endsolid t\n";
}

class ServeReloadTest : public ::testing::Test {
 protected:
  void SetUp() override { URDFSNAP_REQUIRE_GL(); }
  // Polls /api/status until the model's generation passes `after`; returns the status.
  nlohmann::json WaitForGeneration(httplib::Client& client, int after) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    nlohmann::json status;
    while (std::chrono::steady_clock::now() < deadline) {
      status = nlohmann::json::parse(client.Get("/api/status")->body);
      if (status["model"].get<int>() > after) return status;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ADD_FAILURE() << "no reload after generation " << after;
    return status;
  }
  std::string RenderError() {
    const test::ProcessResult r = test::RunUrdfsnap("render " + robot_ + " -o " + folder_.Path("never.png"));
    EXPECT_EQ(r.status, 2);
    return r.err;
  }
  test::TempFolder folder_{"serve_reload"};
  std::string robot_ = folder_.Write("lamp.urdf.xacro", kRobot);
};

TEST_F(ServeReloadTest, EditBreakAndFixWhileServing) {
  folder_.Write("params.xacro", Params(1.0, 0.5));
  folder_.Write("head.stl", Tetrahedron(0.2));
  ServeProcess server(robot_ + " --port 0 --yaw 0.3 --distance 3");
  ASSERT_TRUE(server.started()) << server.Stderr();
  auto client = server.Client();
  auto robot = nlohmann::json::parse(client->Get("/api/robot")->body);
  EXPECT_DOUBLE_EQ(robot["joints"][0]["upper"], 1.0);
  EXPECT_EQ(client->Get("/render.png")->status, 200);

  // an edit of the included file: the limit and the picture change
  folder_.Write("params.xacro", Params(2.0, 0.9));
  auto status = WaitForGeneration(*client, 1);
  EXPECT_TRUE(status["error"].is_null());
  robot = nlohmann::json::parse(client->Get("/api/robot")->body);
  EXPECT_DOUBLE_EQ(robot["joints"][0]["upper"], 2.0);
  const auto edited = client->Get("/render.png?j.tilt=1.5");
  ASSERT_EQ(edited->status, 200);
  const std::string png = folder_.Path("edited.png");
  ASSERT_EQ(test::RunUrdfsnap("render " + robot_ + " --yaw 0.3 --distance 3 -j tilt=1.5 -o " + png).status, 0);
  std::ifstream in(png, std::ios::binary);
  EXPECT_TRUE(edited->body == std::string(std::istreambuf_iterator<char>(in), {}));
  EXPECT_TRUE(server.WaitForStderr("urdfsnap: reloaded " + robot_ + ": robot 'lamp'"));

  // a mesh edit shows in the next frame
  const std::string before_mesh = client->Get("/render.png")->body;
  folder_.Write("head.stl", Tetrahedron(0.5));
  status = WaitForGeneration(*client, status["model"]);
  EXPECT_NE(client->Get("/render.png")->body, before_mesh);

  // broken XML in the include: the located error everywhere, the server keeps running
  folder_.Write("params.xacro", "<robot xmlns:xacro='http://www.ros.org/wiki/xacro'>\n  <xacro:property name='tilt_upper'\n</robot>\n");
  status = WaitForGeneration(*client, status["model"]);
  const std::string error = RenderError();
  ASSERT_FALSE(status["error"].is_null());
  EXPECT_EQ(status["error"].get<std::string>() + "\n", error);
  const auto broken = client->Get("/api/robot");
  EXPECT_EQ(broken->status, 422);
  EXPECT_EQ(nlohmann::json::parse(broken->body)["error"].get<std::string>() + "\n", error);
  const auto broken_frame = client->Get("/render.png");
  EXPECT_EQ(broken_frame->status, 422);
  EXPECT_EQ(broken_frame->body, error);
  EXPECT_TRUE(server.WaitForStderr(error.substr(0, error.find('\n'))));

  // fixed: back to normal
  folder_.Write("params.xacro", Params(1.5, 0.5));
  status = WaitForGeneration(*client, status["model"]);
  EXPECT_TRUE(status["error"].is_null());
  EXPECT_EQ(client->Get("/api/robot")->status, 200);
  EXPECT_EQ(client->Get("/render.png")->status, 200);

  // a missing mesh is the model's error too, and its return is noticed without another edit
  std::filesystem::rename(folder_.Path("head.stl"), folder_.Path("head.stl.moved"));
  status = WaitForGeneration(*client, status["model"]);
  ASSERT_FALSE(status["error"].is_null());
  EXPECT_EQ(status["error"].get<std::string>() + "\n", RenderError());
  EXPECT_NE(status["error"].get<std::string>().find("head.stl"), std::string::npos);
  std::filesystem::rename(folder_.Path("head.stl.moved"), folder_.Path("head.stl"));
  status = WaitForGeneration(*client, status["model"]);
  EXPECT_TRUE(status["error"].is_null());
  EXPECT_EQ(client->Get("/render.png")->status, 200);
  EXPECT_EQ(server.Stop(SIGINT), 0);
}

TEST_F(ServeReloadTest, BrokenAtStartIsServedAsItsErrorUntilFixed) {
  folder_.Write("params.xacro", "<robot xmlns:xacro='http://www.ros.org/wiki/xacro'>\n  <xacro:property name='tilt_upper'\n</robot>\n");
  folder_.Write("head.stl", Tetrahedron(0.2));
  const std::string error = RenderError();
  ServeProcess server(robot_ + " --port 0");
  ASSERT_TRUE(server.started()) << server.Stderr();
  // said once on stderr, and by every part of the API the page asks
  const std::string prefix = "urdfsnap: error: ";
  ASSERT_EQ(error.rfind(prefix, 0), 0u) << error;
  const std::string message = error.substr(prefix.size(), error.find('\n') - prefix.size());
  EXPECT_NE(server.Stderr().find("urdfsnap: warning: " + message), std::string::npos) << server.Stderr();
  auto client = server.Client();
  auto status = nlohmann::json::parse(client->Get("/api/status")->body);
  EXPECT_EQ(status["error"].get<std::string>() + "\n", error);
  for (const char* path : {"/api/view", "/api/robot", "/render.png", "/api/fit"}) {
    const auto response = client->Get(path);
    EXPECT_EQ(response->status, 422) << path;
    EXPECT_NE(response->body.find(error.substr(0, error.find('\n'))), std::string::npos) << path << response->body;
  }
  EXPECT_EQ(client->Get("/")->status, 200);
  // fixed: the page's start, its robot and frames
  folder_.Write("params.xacro", Params(1.0, 0.5));
  status = WaitForGeneration(*client, status["model"]);
  EXPECT_TRUE(status["error"].is_null());
  const auto view = client->Get("/api/view");
  ASSERT_EQ(view->status, 200);
  EXPECT_EQ(nlohmann::json::parse(view->body)["case"]["model"], robot_);
  EXPECT_EQ(client->Get("/api/robot")->status, 200);
  EXPECT_EQ(client->Get("/render.png")->status, 200);
  EXPECT_EQ(server.Stop(SIGINT), 0);
  // option values no edit can mend still end it at once, as render does
  const test::ProcessResult bad = test::RunUrdfsnap("serve " + robot_ + " --port 0 --pitch steep");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "urdfsnap: error: --pitch 'steep': expected a finite number\n");
}

}  // namespace
}  // namespace urdfsnap::serve_test
