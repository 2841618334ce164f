// The HTTP API against the binary: frames byte for byte what `urdfsnap render` writes, render's
// error lines for bad values, the joint table and initial view, and the server's start and stop.
#include <signal.h>
#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/urdfsnap_process.h"
#include "gl/backend.h"
#include "serve_process.h"
#include "support/gl_required.h"
#include "support/temp_folder.h"

namespace urdfsnap::serve_test {
namespace {

const std::filesystem::path kSource = URDFSNAP_SOURCE_DIR;
const std::string kMrmXacro = (kSource / "models/mrm_description/urdf/mrm.xacro").string();
const std::string kMeshbot = (kSource / "models/meshbot_description/urdf/meshbot.urdf").string();

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The error line `urdfsnap render` prints for `arguments`, without its newline (its -o a .png
// name in a folder of its own, never written).
std::string RenderError(const std::string& arguments) {
  const test::TempFolder folder("serve_render_error");
  const test::ProcessResult r = test::RunUrdfsnap("render " + arguments + " -o " + folder.Path("never.png"));
  EXPECT_EQ(r.status, 2) << r.err;
  return r.err.substr(0, r.err.find('\n'));
}

class ServeApiTest : public ::testing::Test {
 protected:
  void SetUp() override { URDFSNAP_REQUIRE_GL(); }
  test::TempFolder folder_{"serve_api"};
};

// Views and poses made up here from a seeded generator: a query for the server and the same
// options for `urdfsnap render`.
struct View {
  std::string query, arguments;
};

std::vector<View> MadeUpViews(int count) {
  std::mt19937 random(20261124);
  const auto uniform = [&](double low, double high) {
    return std::to_string(std::uniform_real_distribution<double>(low, high)(random));
  };
  const char* joints[] = {"base_link__link_01", "link_01__link_02", "link_02__link_03",
                          "link_03__link_04", "link_04__link_05"};
  const char* flags[] = {"tf", "collision", "no-grid", "no-tf-names", "no-aa"};
  const char* sizes[] = {"640x480", "320x240", "800x450", "257x311"};
  std::vector<View> views;
  for (int i = 0; i < count; ++i) {
    View v;
    const auto add = [&](const std::string& key, const std::string& value) {
      v.query += (v.query.empty() ? "" : "&") + key + "=" + value;
      v.arguments += " --" + key + " " + value;
    };
    add("yaw", uniform(-3, 6));
    add("pitch", uniform(-1.2, 1.5));
    add("distance", uniform(2, 9));
    add("focal", uniform(-0.5, 0.5) + "," + uniform(-0.5, 0.5) + "," + uniform(0, 2));
    add("size", sizes[i % 4]);
    if (i % 3 == 1) add("alpha", uniform(0.3, 1));
    if (i % 3 == 2) add("background", "255,250,240");
    v.query += std::string("&") + flags[i % 5];
    v.arguments += std::string(" --") + flags[i % 5];
    for (const char* joint : joints) {
      const std::string value = uniform(-2, 2);
      v.query += std::string("&j.") + joint + "=" + value;
      v.arguments += std::string(" -j ") + joint + "=" + value;
    }
    views.push_back(v);
  }
  return views;
}

TEST_F(ServeApiTest, FramesAreWhatRenderWritesByteForByte) {
  ServeProcess server(kMrmXacro + " --port 0");
  ASSERT_TRUE(server.started()) << server.first_line() << server.Stderr();
  auto client = server.Client();
  int n = 0;
  for (const View& view : MadeUpViews(6)) {
    SCOPED_TRACE(view.query);
    const auto frame = client->Get("/render.png?" + view.query);
    ASSERT_TRUE(frame);
    ASSERT_EQ(frame->status, 200) << frame->body;
    EXPECT_EQ(frame->get_header_value("Content-Type"), "image/png");
    const std::string png = folder_.Path("render" + std::to_string(n++) + ".png");
    const test::ProcessResult r = test::RunUrdfsnap("render " + kMrmXacro + view.arguments + " -o " + png);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(frame->body == ReadFile(png)) << "the frame differs from render's " << png;
  }
  // the server's own options are every frame's start (here a mesh robot fitted in view)
  ServeProcess meshbot(kMeshbot + " --port 0 --fit --yaw 2 --collision");
  ASSERT_TRUE(meshbot.started()) << meshbot.Stderr();
  const auto frame = meshbot.Client()->Get("/render.png?size=500x400&tf");
  ASSERT_TRUE(frame);
  ASSERT_EQ(frame->status, 200) << frame->body;
  const std::string png = folder_.Path("meshbot.png");
  ASSERT_EQ(test::RunUrdfsnap("render " + kMeshbot + " --fit --yaw 2 --collision --size 500x400 --tf -o " + png).status, 0);
  EXPECT_TRUE(frame->body == ReadFile(png));
}

TEST_F(ServeApiTest, GlBackendOptionMakesTheOneRendererAndVerboseSaysSoOnce) {
  for (const gl::Backend backend : gl::CompiledInBackends()) {
    URDFSNAP_REQUIRE_GL_BACKEND(backend);
    const std::string name(gl::BackendName(backend));
    SCOPED_TRACE(name);
    // the variable (which the server inherits) names another backend: the option wins
    const char* was = std::getenv(gl::kBackendVariable);
    const std::string saved = was ? was : "";
    setenv(gl::kBackendVariable, backend == gl::Backend::kEgl ? "osmesa" : "egl", 1);
    ServeProcess server("--gl-backend " + name + " --verbose " + kMrmXacro + " --port 0");
    was ? setenv(gl::kBackendVariable, saved.c_str(), 1) : unsetenv(gl::kBackendVariable);
    ASSERT_TRUE(server.started()) << server.first_line() << server.Stderr();
    const std::string line = "urdfsnap: GL backend " + name + " (--gl-backend " + name + "): ";
    // said when the context was made, for the initial view, before the address was printed
    EXPECT_EQ(server.Stderr().rfind(line, 0), 0u) << server.Stderr();
    auto client = server.Client();
    int n = 0;
    for (const View& view : MadeUpViews(5)) {
      const auto frame = client->Get("/render.png?" + view.query);
      ASSERT_TRUE(frame);
      ASSERT_EQ(frame->status, 200) << frame->body;
      const std::string png = folder_.Path(name + std::to_string(n++) + ".png");
      const test::ProcessResult r =
          test::RunUrdfsnap("render " + kMrmXacro + view.arguments + " --gl-backend " + name + " -o " + png);
      ASSERT_EQ(r.status, 0) << r.err;
      EXPECT_TRUE(frame->body == ReadFile(png)) << "the frame differs from render's " << png;
    }
    // one renderer for every frame (no-aa's too, whose context is another): one line
    EXPECT_EQ(server.Stop(SIGTERM), 0);
    const std::string err = server.Stderr();
    EXPECT_EQ(err.find(line), err.rfind(line)) << err;
  }
}

TEST_F(ServeApiTest, BadValuesAnswerRendersErrorLine) {
  ServeProcess server(kMrmXacro + " --port 0");
  ASSERT_TRUE(server.started()) << server.Stderr();
  auto client = server.Client();
  const std::pair<std::string, std::string> cases[] = {
      {"yaw=abc", "--yaw abc"},
      {"size=0x480", "--size 0x480"},
      {"background=300,0,0", "--background 300,0,0"},
      {"focal=1,2", "--focal 1,2"},
      {"distance=-1", "--distance -1"},
      {"j.elbow=1", "-j elbow=1"},
      {"j.link_01__link_02=bent", "-j link_01__link_02=bent"},
      {"fixed-frame=nowhere", "--fixed-frame nowhere"},
  };
  for (const auto& [query, arguments] : cases) {
    const auto response = client->Get("/render.png?" + query);
    ASSERT_TRUE(response);
    EXPECT_EQ(response->status, 400) << query;
    EXPECT_EQ(response->body, RenderError(kMrmXacro + " " + arguments) + "\n") << query;
  }
  const auto unknown = client->Get("/render.png?jaw=1");
  EXPECT_EQ(unknown->status, 400);
  EXPECT_EQ(unknown->body.rfind("urdfsnap: error: unknown option 'jaw'", 0), 0u) << unknown->body;
  const auto big = client->Get("/render.png?size=5000x100");
  EXPECT_EQ(big->status, 400);
  EXPECT_EQ(big->body, "urdfsnap: error: --size '5000x100': urdfsnap serve renders at most 4096x4096 "
                       "pixels (--max-size)\n");
}

TEST_F(ServeApiTest, RobotAndInitialView) {
  ServeProcess server(kMrmXacro + " --port 0 --yaw 0.25 --no-grid --background 10,20,30 "
                      "-j link_01__link_02=0.5 --package mrm_description=" + (kSource / "models/mrm_description").string());
  ASSERT_TRUE(server.started()) << server.Stderr();
  auto client = server.Client();
  const auto robot = nlohmann::json::parse(client->Get("/api/robot")->body);
  EXPECT_EQ(robot["name"], "mrm");
  ASSERT_EQ(robot["joints"].size(), 5u);
  EXPECT_EQ(robot["joints"][1]["name"], "link_01__link_02");
  EXPECT_DOUBLE_EQ(robot["joints"][1]["lower"], -3.14);
  EXPECT_DOUBLE_EQ(robot["joints"][1]["upper"], 3.14);
  const auto view = nlohmann::json::parse(client->Get("/api/view")->body);
  EXPECT_EQ(view["options"]["yaw"], "0.25");
  EXPECT_EQ(view["options"]["pitch"], "0.785398");  // RViz's
  EXPECT_EQ(view["options"]["no-grid"], true);
  EXPECT_EQ(view["options"]["background"], "10,20,30");
  EXPECT_DOUBLE_EQ(view["joints"]["link_01__link_02"], 0.5);
  EXPECT_EQ(view["case"]["model"], kMrmXacro);
  EXPECT_EQ(view["case"]["options"]["no-grid"], true);
  const auto status = nlohmann::json::parse(client->Get("/api/status")->body);
  EXPECT_EQ(status["model"], 1);
  EXPECT_TRUE(status["error"].is_null());
  EXPECT_EQ(status["camera"], false);   // the orbit view: the page's orbit controls are on
  EXPECT_EQ(status["camera_view"], "");
  // the page and its parts, embedded
  const auto page = client->Get("/");
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("<script src=\"page.js\""), std::string::npos);
  EXPECT_NE(page->get_header_value("Content-Security-Policy").find("default-src 'none'"), std::string::npos);
  for (const char* part : {"/page.js", "/page.css", "/favicon.svg"}) EXPECT_EQ(client->Get(part)->status, 200) << part;
}

TEST_F(ServeApiTest, FitFramesTheRobotOrOneLink) {
  ServeProcess server(kMrmXacro + " --port 0 --fit --yaw 0.25 --package mrm_description=" +
                      (kSource / "models/mrm_description").string());
  ASSERT_TRUE(server.started()) << server.Stderr();
  auto client = server.Client();
  EXPECT_EQ(nlohmann::json::parse(client->Get("/api/robot")->body)["links"][0], "base_link");
  // the whole robot: the view `render --fit` draws, which is where the page started
  const auto initial = nlohmann::json::parse(client->Get("/api/view")->body);
  const auto fit = client->Get("/api/fit?yaw=0.25&distance=40");
  ASSERT_EQ(fit->status, 200) << fit->body;
  const auto whole = nlohmann::json::parse(fit->body);
  EXPECT_DOUBLE_EQ(whole["yaw"], 0.25);
  EXPECT_NEAR(whole["distance"].get<double>(), std::stod(initial["options"]["distance"].get<std::string>()), 1e-5);
  // one link: nearer, looking at that link's middle; the same direction
  const auto link = client->Get("/api/fit?yaw=0.25&link=link_05");
  ASSERT_EQ(link->status, 200) << link->body;
  const auto focused = nlohmann::json::parse(link->body);
  EXPECT_DOUBLE_EQ(focused["yaw"], 0.25);
  EXPECT_LT(focused["distance"].get<double>(), whole["distance"].get<double>() / 2);
  EXPECT_NE(focused["focal"], whole["focal"]);
  // the link where the arm is bent elsewhere: its middle moves with the pose
  const auto bent = nlohmann::json::parse(client->Get("/api/fit?yaw=0.25&link=link_05&j.link_01__link_02=1.5")->body);
  EXPECT_NE(bent["focal"], focused["focal"]);
  // errors in render's words
  const auto unknown = client->Get("/api/fit?link=elbow");
  EXPECT_EQ(unknown->status, 400);
  EXPECT_EQ(nlohmann::json::parse(unknown->body)["error"], "urdfsnap: error: link 'elbow' is not a link of robot 'mrm'");
  EXPECT_EQ(client->Get("/api/fit?yaw=abc")->status, 400);
  EXPECT_EQ(server.Stop(SIGINT), 0);

  // a frame without geometry, nothing below it (a tool point): the link it hangs from
  const std::string tool = folder_.Write("tool.urdf", R"(<robot name="t">
  <link name="base"><visual><geometry><box size="2 2 2"/></geometry></visual></link>
  <link name="hand"><visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual></link>
  <link name="tcp"/>
  <joint name="arm" type="fixed"><parent link="base"/><child link="hand"/><origin xyz="0 0 3"/></joint>
  <joint name="tip" type="fixed"><parent link="hand"/><child link="tcp"/><origin xyz="0 0 0.1"/></joint>
</robot>)");
  ServeProcess tooled(tool + " --port 0");
  ASSERT_TRUE(tooled.started()) << tooled.Stderr();
  auto tool_client = tooled.Client();
  const auto at_tcp = nlohmann::json::parse(tool_client->Get("/api/fit?link=tcp")->body);
  const auto at_hand = nlohmann::json::parse(tool_client->Get("/api/fit?link=hand")->body);
  EXPECT_EQ(at_tcp, at_hand);
  // (the fit looks along the line of sight through the silhouette's centre: a point inside the hand)
  EXPECT_NEAR(at_hand["focal"][2].get<double>(), 3, 0.05);
  EXPECT_EQ(tooled.Stop(SIGINT), 0);
}

TEST_F(ServeApiTest, StartStopAndBind) {
  // a bad initial option is render's error, before anything is served
  const test::ProcessResult bad = test::RunUrdfsnap("serve " + kMrmXacro + " --port 0 --yaw abc");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "urdfsnap: error: --yaw 'abc': expected a finite number\n");
  EXPECT_EQ(bad.out, "");
  // (a broken model at the start is served as its error: serve_reload_test.cpp)
  ServeProcess server(kMrmXacro + " --port 0");
  ASSERT_TRUE(server.started()) << server.Stderr();
  // the port taken: a clear error
  const test::ProcessResult taken = test::RunUrdfsnap("serve " + kMrmXacro + " --port " + std::to_string(server.port()));
  EXPECT_EQ(taken.status, 2);
  EXPECT_NE(taken.err.find("cannot listen on 127.0.0.1:" + std::to_string(server.port())), std::string::npos) << taken.err;
  // only loopback names, unless --bind says otherwise (DNS rebinding)
  auto client = server.Client();
  EXPECT_EQ(client->Get("/api/robot", {{"Host", "attacker.example:80"}})->status, 403);
  EXPECT_EQ(client->Get("/api/robot", {{"Host", "localhost:9000"}})->status, 200);
  // Ctrl-C with a kept-alive connection open: a clean stop
  ASSERT_EQ(client->Get("/api/status")->status, 200);
  EXPECT_EQ(server.Stop(SIGINT), 0);
  EXPECT_NE(server.Stderr().find("urdfsnap: stopped"), std::string::npos);

  ServeProcess open(kMrmXacro + " --port 0 --bind 0.0.0.0");
  EXPECT_EQ(open.first_line().rfind("urdfsnap: serving http://0.0.0.0:", 0), 0u) << open.first_line();
  EXPECT_NE(open.Stderr().find("urdfsnap: warning: --bind 0.0.0.0: anyone who can reach this address"),
            std::string::npos) << open.Stderr();
  EXPECT_EQ(open.Stop(SIGTERM), 0);
}

}  // namespace
}  // namespace urdfsnap::serve_test
