// A bag served with a time slider (`urdfsnap serve run.mcap --rviz view.rviz`): /api/status gives
// the recording's length, /render.png?at=T is byte for byte `render --bag run.mcap --at T` with the
// same options (the .rviz file's displays showing the bag's messages up to T), a bad 'at' is
// render's error line, and 'at' is refused when no bag is served; through a calibrated camera too.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bag/test_bags.h"
#include "cli/urdfsnap_process.h"
#include "serve_process.h"
#include "support/gl_required.h"
#include "support/temp_folder.h"

namespace urdfsnap::serve_test {
namespace {

const std::string kView = "size=320x240&distance=8&focal=0.6,0,0.8";
const std::string kViewArguments = " --size 320x240 --distance 8 --focal 0.6,0,0.8";

class ServeRecordingTest : public ::testing::Test {
 protected:
  void SetUp() override { URDFSNAP_REQUIRE_GL(); }
  test::TempFolder folder_{"serve_recording"};
};

TEST_F(ServeRecordingTest, FramesAtATimeAreRenderBagAtThatTime) {
  const std::string bag = test::TestBag("displays_moving.mcap");
  const std::string config = folder_.Path("view.rviz");
  std::ofstream(config) << "Visualization Manager:\n  Displays:\n    - Class: rviz/PointCloud2\n      Enabled: true\n"
                           "      Topic: /cloud\n    - Class: rviz/MarkerArray\n      Enabled: true\n      Topic: /markers\n"
                           "  Global Options:\n    Fixed Frame: odom\n";
  ServeProcess server(bag + " --rviz " + config + " --port 0");
  ASSERT_TRUE(server.started()) << server.first_line() << server.Stderr();
  auto client = server.Client();
  const auto status = client->Get("/api/status");
  ASSERT_TRUE(status);
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(status->body)["recording"]["duration"].get<double>(), 3.0);
  // forward (the displays kept between requests, fed only the messages in between), then back
  // (made again from the bag's start), then forward again
  for (const char* at : {"0.4", "1.2", "2.9", "0.7", "1.6"}) {
    const auto frame = client->Get("/render.png?at=" + std::string(at) + "&" + kView);
    ASSERT_TRUE(frame);
    ASSERT_EQ(frame->status, 200) << frame->body;
    const std::string png = folder_.Path(std::string("still_") + at + ".png");
    const test::ProcessResult r =
        test::RunUrdfsnap("render --bag " + bag + " --at " + at + " --rviz " + config + kViewArguments + " -o " + png);
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream in(png, std::ios::binary);
    EXPECT_TRUE(frame->body == std::string(std::istreambuf_iterator<char>(in), {})) << "at " << at;
  }
  const auto bad = client->Get("/render.png?at=x&" + kView);
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(bad->body, "urdfsnap: error: at 'x': expected a finite number\n");
}

// `serve BAG --camera-info FILE`: the slider moves time, the view stays the calibrated camera's:
// each moment is byte for byte `render --bag BAG --at T` through the same camera, and fitting the
// view is refused with the reason; /api/status tells the page its orbit controls have nothing to move.
TEST_F(ServeRecordingTest, ARecordingIsServedThroughACalibratedCamera) {
  const std::string bag = test::TestBag("displays_moving.mcap");
  const std::string config = folder_.Path("view.rviz");
  std::ofstream(config) << "Visualization Manager:\n  Displays:\n    - Class: rviz/MarkerArray\n      Enabled: true\n"
                           "      Topic: /markers\n  Global Options:\n    Fixed Frame: odom\n";
  const std::string info = folder_.Path("cam.yaml");
  std::ofstream(info) << "image_width: 320\nimage_height: 240\n"
                         "camera_matrix: {rows: 3, cols: 3, data: [200, 0, 160, 0, 200, 120, 0, 0, 1]}\n"
                         "projection_matrix: {rows: 3, cols: 4, data: [200, 0, 160, 0, 0, 200, 120, 0, 0, 0, 1, 0]}\n";
  const std::string camera = " --rviz " + config + " --camera-info " + info + " --camera-pose 0,0,6,1,0,0,0";
  ServeProcess server(bag + camera + " --port 0");
  ASSERT_TRUE(server.started()) << server.first_line() << server.Stderr();
  auto client = server.Client();
  const auto status = client->Get("/api/status");
  ASSERT_TRUE(status);
  const nlohmann::json status_json = nlohmann::json::parse(status->body);
  EXPECT_TRUE(status_json["camera"].get<bool>()) << "the page's orbit controls are off";
  EXPECT_EQ(status_json["camera_view"], "cam.yaml at pose 0,0,6,1,0,0,0") << "the page's status line names the camera";
  std::string earlier;
  for (const char* at : {"0.4", "2.9"}) {
    const auto frame = client->Get("/render.png?at=" + std::string(at));
    ASSERT_TRUE(frame);
    ASSERT_EQ(frame->status, 200) << frame->body;
    const std::string png = folder_.Path(std::string("camera_") + at + ".png");
    const test::ProcessResult r = test::RunUrdfsnap("render --bag " + bag + " --at " + at + camera + " -o " + png);
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream in(png, std::ios::binary);
    EXPECT_TRUE(frame->body == std::string(std::istreambuf_iterator<char>(in), {})) << "at " << at;
    EXPECT_NE(frame->body, earlier) << "the moment moves the robot and its markers";
    earlier = frame->body;
  }
  const auto fit = client->Get("/api/fit");
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->status, 400);
  EXPECT_NE(fit->body.find("--fit frames the orbit view; a camera (--camera-info, --camera-frame, --camera-pose) is placed as given"), std::string::npos) << fit->body;
}

TEST_F(ServeRecordingTest, AtWithoutABagIsRefused) {
  const std::string mrm = std::string(URDFSNAP_SOURCE_DIR) + "/models/mrm_description/urdf/mrm.urdf";
  ServeProcess server(mrm + " --port 0");
  ASSERT_TRUE(server.started()) << server.first_line() << server.Stderr();
  const auto frame = server.Client()->Get("/render.png?at=1");
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->status, 400);
  EXPECT_NE(frame->body.find("at: a moment of a recording"), std::string::npos) << frame->body;
}

}  // namespace
}  // namespace urdfsnap::serve_test
