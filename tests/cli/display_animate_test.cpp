// RViz's message displays in `animate`, through the binary, on a bag written by the MCAP project's
// writer (tests/node/make_display_bags.mjs: a moving arm on a moving base, a 10 Hz cloud, a path,
// markers with a lifetime, a frame_locked marker, a DELETEALL and a hostile marker): each frame is
// byte for byte `render --bag --at` of its moment, markers come and go as RViz shows them, an MP4
// decodes to those frames, the hostile message is one warning, and a camera in the bag's TF sees
// the displays.
#include <string>

#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "image/png_reader.h"
#include "video/ffmpeg_tools.h"

namespace urdfsnap::cli_test {
namespace {

const std::string kDisplays =
    " --fixed-frame odom --display MarkerArray:/markers --display PointCloud2:/cloud --display Path:/path"
    " --size 320x240 --yaw 0.6 --pitch 0.5 --distance 8 --focal 0.6,0,0.8";

class DisplayAnimateTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
    bag_ = test::TestBag("displays_moving.mcap");
  }
  // Runs urdfsnap with ARGUMENTS, expecting success; returns its messages.
  std::string Ok(const std::string& arguments) {
    const Result result = RunUrdfsnap(arguments);
    EXPECT_EQ(result.status, 0) << arguments << "\n" << result.output;
    return result.output;
  }
  std::string Frame(int k) const {
    char name[32];
    std::snprintf(name, sizeof name, "frames/%03d.png", k);
    return Path(name);
  }
  std::string bag_;
};

// Pixels within 40 of `rgb` on every channel.
int Count(const image::Image& image, int r, int g, int b) {
  int count = 0;
  for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    if (std::abs(image.rgb[i] - r) <= 40 && std::abs(image.rgb[i + 1] - g) <= 40 && std::abs(image.rgb[i + 2] - b) <= 40) {
      ++count;
    }
  }
  return count;
}

// Pixels that differ between two images of the same size.
int Differing(const image::Image& a, const image::Image& b) {
  int count = 0;
  for (size_t i = 0; i + 2 < a.rgb.size() && i + 2 < b.rgb.size(); i += 3) {
    if (a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2]) ++count;
  }
  return count;
}

TEST_F(DisplayAnimateTest, EachFrameIsRenderOfItsMomentWithTheBagsMessages) {
  const std::string output = Ok("animate " + bag_ + kDisplays + " --fps 10 -q -o " + Path("frames/%03d.png"));
  // the line strip claiming 10^8 points at 1.5 s: one warning, the frames still drawn
  const std::string claim = "a sequence of 100000000 elements";
  ASSERT_NE(output.find(claim), std::string::npos) << output;
  EXPECT_EQ(output.find(claim), output.rfind(claim)) << output;
  // (frame 0 is the first messages' moment; 15 and 16 straddle the hostile message; 30 is the end)
  for (int k : {0, 7, 15, 16, 26, 30}) {
    const std::string still = Path("still_" + std::to_string(k) + ".png");
    Ok("render --bag " + bag_ + " --at " + std::to_string(k / 10.0) + kDisplays + " -o " + still);
    EXPECT_EQ(ReadBytes(Frame(k)), ReadBytes(still)) << "frame " << k;
  }
  // the displays are drawn: the cloud's rainbow, the path's green, and what is not there without them
  const image::Image shown = image::ReadPng(Frame(7));
  Ok("render --bag " + bag_ + " --at 0.7 --fixed-frame odom --size 320x240 --yaw 0.6 --pitch 0.5 --distance 8 "
     "--focal 0.6,0,0.8 -o " + Path("bare.png"));
  const image::Image bare = image::ReadPng(Path("bare.png"));
  EXPECT_GT(Count(shown, 25, 255, 0), Count(bare, 25, 255, 0) + 10);     // the Path display's colour
  EXPECT_GT(Differing(shown, bare), 600);   // the cloud's ring, the path, a marker
}

TEST_F(DisplayAnimateTest, MarkersLiveTheirLifetimeFollowTheirFrameAndGoAtDeleteAll) {
  Ok("animate " + bag_ + kDisplays + " --fps 10 -q -o " + Path("frames/%03d.png"));
  // the cube's colour (0, 0.8, 1) lit and shaded: blue and green well above red
  const auto cyan = [&](int k) {
    const image::Image frame = image::ReadPng(Frame(k));
    int count = 0;
    for (size_t i = 0; i + 2 < frame.rgb.size(); i += 3) {
      if (frame.rgb[i + 2] > frame.rgb[i] + 80 && frame.rgb[i + 1] > frame.rgb[i] + 50) ++count;
    }
    return count;
  };
  const auto orange = [&](int k) { return Count(image::ReadPng(Frame(k)), 255, 128, 0); };
  // (the cloud's rainbow has a few cyan points)
  EXPECT_GT(cyan(12), cyan(4) + 20);    // the frame_locked cube comes at 0.5 s ...
  EXPECT_GT(cyan(24), cyan(26) + 20);   // ... follows link_05 as the arm turns, and goes at 2.5 s
  // a trail sphere every 0.5 s living 0.6 s: one at 0.4 s, two at 0.5 s and 0.6 s... (counted in
  // pixels: two spheres cover about twice what one does)
  EXPECT_GT(orange(0), 20);
  EXPECT_GT(orange(5), orange(0) * 3 / 2);
  EXPECT_LT(orange(8), orange(5) * 3 / 4);
}

TEST_F(DisplayAnimateTest, AnMp4DecodesToTheFramesWithDisplays) {
  const std::string video = Path("run.mp4");
  Ok("animate " + bag_ + kDisplays + " --fps 10 -q -o " + video);
  Ok("animate " + bag_ + kDisplays + " --fps 10 -q -o " + Path("frames/%03d.png"));
  const test::ProbedVideo probed = test::Probe(video);
  EXPECT_EQ(probed.frames, 31);
  const std::vector<image::Image> decoded = test::DecodeFrames(video, 320, 240);
  ASSERT_EQ(decoded.size(), 31u);
  for (int k : {3, 17, 29}) {
    // H.264 at CRF 20 with 4:2:0 chroma blurs the thin rainbow ring and path more than a robot
    const test::FrameDifference difference = test::Compare(decoded[k], image::ReadPng(Frame(k)));
    EXPECT_LE(difference.mean, 3.0) << "frame " << k;
    EXPECT_LE(difference.percentile_99, 30) << "frame " << k;
  }
}

TEST_F(DisplayAnimateTest, AnRvizConfigsDisplaysAndFixedFrameAreEveryFrames) {
  const std::string config = Write("view.rviz", R"(Visualization Manager:
  Class: ""
  Displays:
    - Class: rviz/PointCloud2
      Name: lidar
      Enabled: true
      Topic: /cloud
      Style: Boxes
      Size (m): 0.08
      Color Transformer: FlatColor
      Color: 0; 255; 0
    - Class: rviz_default_plugins/MarkerArray
      Name: markers
      Enabled: true
      Topic: /markers
  Global Options:
    Fixed Frame: odom
)");
  const std::string view = " --rviz " + config + " --size 320x240 --yaw 0.6 --pitch 0.5 --distance 8 --focal 0.6,0,0.8";
  Ok("animate " + bag_ + view + " --fps 10 -q -o " + Path("frames/%03d.png"));
  Ok("render --bag " + bag_ + " --at 1" + view + " -o " + Path("still.png"));
  EXPECT_EQ(ReadBytes(Frame(10)), ReadBytes(Path("still.png")));
  // the cloud as green boxes
  EXPECT_GT(Count(image::ReadPng(Frame(10)), 0, 200, 0), 300);
}

TEST_F(DisplayAnimateTest, PrintFrameOfABagsDisplaysIsAnError) {
  const Result result = RunUrdfsnap("animate " + bag_ + " --display MarkerArray:/markers --print-frame 3");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--print-frame: the frames show the bag's messages"), std::string::npos) << result.output;
}

TEST_F(DisplayAnimateTest, DisplaysAreSeenThroughACameraInTheBagsTf) {
  // 3 m above the lidar (a frame of the bag's TF, not a link), looking down on the cloud's ring
  const std::string camera = " --camera-info " + Write("cam.yaml", R"(image_width: 320
image_height: 240
camera_matrix: {rows: 3, cols: 3, data: [150, 0, 160, 0, 150, 120, 0, 0, 1]}
distortion_model: plumb_bob
distortion_coefficients: {rows: 1, cols: 5, data: [0, 0, 0, 0, 0]}
)") + " --camera-frame lidar --camera-pose 0,0,3,1,0,0,0";
  const std::string displays = " --fixed-frame odom --display PointCloud2:/cloud --display Path:/path";
  Ok("animate " + bag_ + displays + camera + " --fps 10 -q -o " + Path("frames/%03d.png"));
  Ok("render --bag " + bag_ + " --at 0.7" + displays + camera + " -o " + Path("still.png"));
  EXPECT_EQ(ReadBytes(Frame(7)), ReadBytes(Path("still.png")));
  Ok("render --bag " + bag_ + " --at 0.7 --fixed-frame odom" + camera + " -o " + Path("bare.png"));
  const image::Image shown = image::ReadPng(Frame(7));
  const image::Image bare = image::ReadPng(Path("bare.png"));
  EXPECT_GT(Count(shown, 25, 255, 0), Count(bare, 25, 255, 0) + 10);   // the path's green
  EXPECT_GT(Differing(shown, bare), 600);                               // and the cloud's ring
}

}  // namespace
}  // namespace urdfsnap::cli_test
