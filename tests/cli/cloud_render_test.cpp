// PointCloud2 and LaserScan displays through the binary: `render --bag FILE --at T` with
// `--display PointCloud2:TOPIC` / `LaserScan:TOPIC` or a .rviz config draws the clouds and the scan
// of a bag written by other tools (tests/node/make_cloud_bags.mjs), in the colours RViz's
// transformers give them; a cloud that lies about its size is a warning naming the message, the
// rest of the picture still drawn.
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

// mrm in base_link seen from the front (+x) and above: the rgb wall at x = 1.5 m faces the camera
const std::string kView = " --size 320x240 --yaw 0 --pitch 0.3 --distance 3 --focal 0.5,0,0.5";

class CloudRenderTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
  }
  // The image `urdfsnap render --bag clouds.mcap --at 0 ARGUMENTS` writes, and its messages.
  image::Image Render(const std::string& arguments, std::string* output = nullptr,
                      const std::string& bag = "clouds.mcap") {
    const std::string out = Path("render_" + std::to_string(renders_++) + ".png");
    const Result result = RunUrdfsnap("render --bag " + test::TestBag(bag) + " --at 0" + kView + arguments + " -o " + out);
    EXPECT_EQ(result.status, 0) << arguments << "\n" << result.output;
    if (output) *output = result.output;
    return image::ReadPng(out);
  }
};

// How many pixels are close to `rgb` (within `tolerance` per channel: points of 0.01 m cover a pixel
// or two, blended with the background at their edges).
int Count(const image::Image& image, int r, int g, int b, int tolerance = 40) {
  int count = 0;
  for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    if (std::abs(image.rgb[i] - r) <= tolerance && std::abs(image.rgb[i + 1] - g) <= tolerance &&
        std::abs(image.rgb[i + 2] - b) <= tolerance) {
      ++count;
    }
  }
  return count;
}

TEST_F(CloudRenderTest, RgbCloudIsDrawnInItsOwnColours) {
  const image::Image robot = Render("");
  const image::Image cloud = Render(" --display PointCloud2:/cloud_rgb");
  // the wall's top-left corner: (255, 80, 0); its bottom right (27, 80, 228)
  EXPECT_GT(Count(cloud, 255, 80, 0), Count(robot, 255, 80, 0));
}

TEST_F(CloudRenderTest, IntensityCloudAndScanTakeTheRainbow) {
  const image::Image robot = Render("");
  const image::Image image = Render(" --display PointCloud2:/cloud_intensity --display LaserScan:/scan");
  // (the robot is red: the lowest intensity's red cannot be told from it)
  EXPECT_GT(Count(image, 0, 255, 0), Count(robot, 0, 255, 0));       // the middle intensities: green
  EXPECT_GT(Count(image, 255, 0, 255), Count(robot, 255, 0, 255));   // the highest: magenta
}

TEST_F(CloudRenderTest, RvizConfigSetsStyleAndColours) {
  const std::string config = Path("clouds.rviz");
  std::ofstream(config) << R"(Visualization Manager:
  Class: ""
  Displays:
    - Class: rviz/PointCloud2
      Name: wall
      Enabled: true
      Topic: /cloud_rgb
      Style: Boxes
      Size (m): 0.04
      Color Transformer: FlatColor
      Color: 0; 255; 0
  Global Options:
    Fixed Frame: base_link
)";
  const image::Image image = Render(" --rviz " + config);
  // boxes lit by box.geom's lightness: the +x face towards the camera is 0.5 of the colour
  EXPECT_GT(Count(image, 0, 128, 0, 12), 100);
}

TEST_F(CloudRenderTest, CloudThatLiesIsAWarningNamingTheMessage) {
  std::string output;
  Render(" --display PointCloud2:/cloud_rgb", &output, "cloud_lies.mcap");
  EXPECT_NE(output.find("urdfsnap: warning: "), std::string::npos) << output;
  EXPECT_NE(output.find("message 1 on '/cloud_rgb'"), std::string::npos) << output;
  EXPECT_NE(output.find("data holds 16 bytes, fewer than the 1600000000"), std::string::npos) << output;
}

}  // namespace
}  // namespace urdfsnap::cli_test
