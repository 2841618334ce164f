// `urdfsnap render --bag FILE --at T --underlay-topic TOPIC` against the binary: the camera image a
// bag holds at the moment drawn behind the robot, as RViz's Camera display shows it, in every
// encoding it shows (tests/node/make_test_bags.mjs writes rover_camera.mcap's pictures, recomputed
// here); hostile messages (a step or size that lies, an unknown encoding) are one error line with
// nothing written.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>
#include <jpeglib.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 40, kHeight = 24;

// make_test_bags.mjs's pictures: A at 0 s, B at 1 s; `Grey` the one-channel images' values.
std::array<int, 3> Picture(int x, int y, bool b) {
  return b ? std::array{255 - x * 6, 255 - y * 10, x * 6} : std::array{x * 6, y * 10, 255 - x * 6};
}
int Grey(int x, int y) { return 5 * x + y; }

image::Image Expected(const std::function<std::array<int, 3>(int, int)>& pixel) {
  image::Image image{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 3)};
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::array<int, 3> p = pixel(x, y);
      for (int c = 0; c < 3; ++c) image.rgb[3 * (y * kWidth + x) + c] = static_cast<std::uint8_t>(p[c]);
    }
  }
  return image;
}

// The largest difference of one sample between two images of one size, and the mean.
struct Difference {
  int most = 0;
  double mean = 0;
};
Difference Compare(const image::Image& a, const image::Image& b) {
  Difference d;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const int difference = std::abs(a.rgb[i] - b.rgb[i]);
    d.most = std::max(d.most, difference);
    d.mean += difference;
  }
  d.mean /= static_cast<double>(a.rgb.size());
  return d;
}

class BagUnderlayTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
  }
  // The picture `render --bag rover_camera.mcap ARGUMENTS` draws.
  image::Image Render(const std::string& arguments) {
    const std::string out = Path("render_" + std::to_string(renders_++) + ".png");
    const Result result = RunUrdfsnap("render --bag " + bag_ + " " + arguments + " -o " + out);
    EXPECT_EQ(result.status, 0) << arguments << "\n" << result.output;
    const image::Image image = image::ReadPng(out);
    EXPECT_EQ(image.width, kWidth);
    return image;
  }
  // Runs a render that must fail: exit 2, one error line holding `expected`, no output file.
  void Fails(const std::string& arguments, const std::string& expected) {
    const Result result = RunUrdfsnap("render " + arguments + " -o " + Path("bad.png"));
    EXPECT_EQ(result.status, 2) << arguments << "\n" << result.output;
    EXPECT_EQ(result.output.rfind("urdfsnap: error: ", 0), 0u) << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(Path("bad.png")));
  }
  const std::string bag_ = test::TestBag("rover_camera.mcap");
  // 10 m above the rover looking up: no robot in the picture, which is the camera image alone
  const std::string away_ = "--camera-pose 0,0,10,0,0,0,1 --size 40x24 --underlay-topic ";
  int renders_ = 0;
};

TEST_F(BagUnderlayTest, TheLatestImageAtOrBeforeTheMomentIsBehindTheRobot) {
  const image::Image a = Expected([](int x, int y) { return Picture(x, y, false); });
  const image::Image b = Expected([](int x, int y) { return Picture(x, y, true); });
  // picture A stamped at 0 s, B at 1 s (rows padded: the step is honoured)
  EXPECT_EQ(Render(away_ + "/camera/rgb8 --at 0").rgb, a.rgb);
  EXPECT_EQ(Render(away_ + "/camera/rgb8 --at 0.9").rgb, a.rgb);
  EXPECT_EQ(Render(away_ + "/camera/rgb8 --at 1").rgb, b.rgb);
  // the same picture in the other colour encodings and as a PNG
  for (const char* topic : {"/camera/bgr8", "/camera/rgba8", "/camera/bgra8", "/camera/png"}) {
    EXPECT_EQ(Render(away_ + topic).rgb, a.rgb) << topic;
  }
  // the robot over it: half and half where it is (RViz's Overlay Alpha); at alpha 1 the image alone
  const std::string down = "--camera-pose 0,0,1.2,1,0,0,0 --size 40x24 --fov 90 --underlay-topic /camera/rgb8";
  const image::Image over = Render(down);
  int robot = 0, image_only = 0;
  for (std::size_t i = 0; i < over.rgb.size(); ++i) (over.rgb[i] == a.rgb[i] ? image_only : robot) += 1;
  EXPECT_GT(robot, 30);
  EXPECT_GT(image_only, 1000);
  EXPECT_EQ(Render(down + " --underlay-alpha 1").rgb, a.rgb);
}

// /camera/moving's picture k: stamped at k / 2 s, logged 0.15 s later.
image::Image Moving(int k) {
  return Expected([k](int x, int y) { return std::array{x * 6, y * 10, k * 40}; });
}

TEST_F(BagUnderlayTest, AnImageIsShownOnceReceivedAsRvizShowsIt) {
  // picture 1 is stamped at 0.5 s but arrives at 0.65 s: until then picture 0 is the newest received
  EXPECT_EQ(Render(away_ + "/camera/moving --at 0.6").rgb, Moving(0).rgb);
  EXPECT_EQ(Render(away_ + "/camera/moving --at 0.7").rgb, Moving(1).rgb);
  EXPECT_EQ(Render(away_ + "/camera/moving --at 2").rgb, Moving(3).rgb);   // picture 4 arrives at 2.15 s
  Fails("--bag " + bag_ + " " + away_ + "/camera/moving --at 0.1",
        "no image on '/camera/moving' received at or before the moment drawn (stamp 1700000000.");
}

TEST_F(BagUnderlayTest, AnimateShowsEachFramesImageAsRenderAtThatMomentDoes) {
  // frames at 0.2 s, 0.4 s, ... 2 s: each the image received by then, in one pass over the bag
  const auto animate = [&](const std::string& view, const std::string& name) {
    const Result result = RunUrdfsnap("animate " + bag_ + " " + view + " --underlay-topic /camera/moving --start 0.2 "
                                      "--fps 5 -q -o " + Path(name + "/%02d.png"));
    EXPECT_EQ(result.status, 0) << result.output;
  };
  animate("--camera-pose 0,0,10,0,0,0,1 --size 40x24", "away");
  for (int k = 0; k < 10; ++k) {
    const int shown = (4 * k + 1) / 10;   // frame k at 0.2 (k + 1) s; picture j arrives at j / 2 + 0.15 s
    EXPECT_EQ(image::ReadPng(Path("away/0" + std::to_string(k) + ".png")).rgb, Moving(shown).rgb) << k;
  }
  // the robot over the images: a frame is the still `render --bag --at` draws at its moment, byte for byte
  const std::string down = "--camera-pose 0,0,1.2,1,0,0,0 --size 40x24 --fov 90";
  animate(down, "down");
  for (const auto& [k, at] : {std::pair{0, "0.2"}, std::pair{2, "0.6"}, std::pair{9, "2"}}) {
    std::ifstream frame(Path("down/0" + std::to_string(k) + ".png"), std::ios::binary);
    Render(down + " --underlay-topic /camera/moving --at " + at);
    std::ifstream still(Path("render_" + std::to_string(renders_ - 1) + ".png"), std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(frame), {}), std::string(std::istreambuf_iterator<char>(still), {}))
        << "frame " << k;
  }
  // a frame before the first image is an error naming the moment
  const Result early = RunUrdfsnap("animate " + bag_ + " " + down + " --underlay-topic /camera/moving --fps 5 -q -o " +
                                   Path("early.mp4"));
  EXPECT_EQ(early.status, 2);
  EXPECT_NE(early.output.find("no image on '/camera/moving' received at or before the moment drawn"), std::string::npos)
      << early.output;
  EXPECT_FALSE(fs::exists(Path("early.mp4")));
}

TEST_F(BagUnderlayTest, GreyAndDepthImagesAreScaledAsRvizShowsThem) {
  EXPECT_EQ(Render(away_ + "/camera/mono8").rgb,
            Expected([](int x, int y) { return std::array{Grey(x, y), Grey(x, y), Grey(x, y)}; }).rgb);
  // 16-bit (big-endian) 1000 + 10 g: the smallest black, the largest white, truncated
  const int low = 1000, high = 1000 + 10 * Grey(kWidth - 1, kHeight - 1);
  EXPECT_EQ(Render(away_ + "/camera/mono16").rgb, Expected([&](int x, int y) {
              const int v = static_cast<int>(double(1000 + 10 * Grey(x, y) - low) / (high - low) * 255);
              return std::array{v, v, v};
            }).rgb);
  // 32FC1 metres 0.5 + g / 1000, NaN at (0, 0) shown black and left out of the range
  const image::Image depth = Render(away_ + "/camera/depth");
  const float near = 0.5f + Grey(0, 1) / 1000.0f, far = 0.5f + Grey(kWidth - 1, kHeight - 1) / 1000.0f;
  const image::Image expected = Expected([&](int x, int y) {
    const int v = x == 0 && y == 0 ? 0 : static_cast<int>((0.5f + Grey(x, y) / 1000.0f - near) / (far - near) * 255);
    return std::array{v, v, v};
  });
  EXPECT_LE(Compare(depth, expected).most, 1);
  EXPECT_EQ(depth.rgb[0], 0);
}

TEST_F(BagUnderlayTest, AJpegIsDecodedAsLibjpegsDefaultsDecodeIt) {
  // tests/data/jpeg/gradients.jpg (40x24, 4:2:0 chroma) in a CompressedImage, against libjpeg's
  // default decoding (accurate IDCT, interpolated chroma), which OpenCV's imdecode and so ROS's
  // compressed image transport use; rounding differs by a level or two
  std::ifstream file(kSource / "tests/data/jpeg/gradients.jpg", std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(file), {}};
  jpeg_decompress_struct decoder;
  jpeg_error_mgr errors;
  decoder.err = jpeg_std_error(&errors);
  jpeg_create_decompress(&decoder);
  jpeg_mem_src(&decoder, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  ASSERT_EQ(jpeg_read_header(&decoder, TRUE), JPEG_HEADER_OK);
  decoder.out_color_space = JCS_RGB;
  jpeg_start_decompress(&decoder);
  ASSERT_EQ(static_cast<int>(decoder.output_width), kWidth);
  image::Image reference{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 3)};
  while (decoder.output_scanline < decoder.output_height) {
    unsigned char* row = &reference.rgb[3 * kWidth * decoder.output_scanline];
    jpeg_read_scanlines(&decoder, &row, 1);
  }
  jpeg_finish_decompress(&decoder);
  jpeg_destroy_decompress(&decoder);
  const Difference d = Compare(Render(away_ + "/camera/jpeg"), reference);
  EXPECT_LE(d.most, 3);
  EXPECT_LT(d.mean, 0.5);
}

TEST_F(BagUnderlayTest, TheCalibrationMayComeFromTheBag) {
  // /camera/camera_info holds this calibration: the topic's message draws what the file draws,
  // rectified and through the lens
  const std::string file = Write("camera.yaml", R"(width: 40
height: 24
distortion_model: plumb_bob
d: [-0.2, 0.05, 0.001, -0.002, 0]
k: [30, 0, 21.25, 0, 31, 11.75, 0, 0, 1]
r: [1, 0, 0, 0, 1, 0, 0, 0, 1]
p: [31, 0, 20.5, 0, 0, 32, 12.25, 0, 0, 0, 1, 0]
)");
  const std::string view = "--camera-pose 0,0,1.2,1,0,0,0 --underlay-topic /camera/rgb8 ";
  for (const std::string lens : {"", " --distort"}) {
    const image::Image from_file = Render(view + "--camera-info " + file + lens);
    EXPECT_EQ(Render(view + "--camera-info-topic /camera/camera_info" + lens).rgb, from_file.rgb) << lens;
    const image::Image a = Expected([](int x, int y) { return Picture(x, y, false); });
    EXPECT_NE(from_file.rgb, a.rgb) << "no robot over the image" << lens;
  }
  // a --size beside it is warned of as beside --camera-info
  const Result sized = RunUrdfsnap("render --bag " + bag_ + " " + view + "--camera-info-topic /camera/camera_info "
                                   "--size 640x480 -o " + Path("sized.png"));
  EXPECT_EQ(sized.status, 0) << sized.output;
  EXPECT_EQ(sized.output, "urdfsnap: warning: --size 640x480 is ignored: the size comes from the calibration "
                          "(--camera-info-topic)\n");
  EXPECT_EQ(image::ReadPng(Path("sized.png")).width, kWidth);
}

TEST_F(BagUnderlayTest, BadImagesAndOptionsAreOneErrorLine) {
  const std::string away = "--bag " + bag_ + " " + away_;
  Fails(away + "/camera/short", "too few for 40x24 pixels at step 120");
  Fails(away + "/camera/step_lies", "step 119 is shorter than a row of 40 rgb8 pixels (120 bytes)");
  Fails(away + "/camera/huge", "image size 40x4000000000 is outside 1x1 to 16384x16384");
  Fails(away + "/camera/yuv", "image encoding 'yuv422' is not one urdfsnap shows");
  Fails(away + "/camera/not_an_image", "compressed image of format 'tiff' is neither JPEG nor PNG");
  Fails(away + "/camera/nowhere", "no topic '/camera/nowhere'");
  Fails(away + "/tf", "carries 'tf2_msgs/msg/TFMessage' messages");
  Fails("--bag " + bag_ + " --camera-pose 0,0,10,0,0,0,1 --size 20x12 --underlay-topic /camera/rgb8",
        "the underlay image is 40x24, the camera's image 20x12");
  Fails("--bag " + bag_ + " --underlay-topic /camera/rgb8", "--underlay-topic needs a camera");
  Fails(kMrm + " --camera-pose 0,0,10,0,0,0,1 --underlay-topic /camera/rgb8", "give the recording with --bag");
  Fails("--bag " + bag_ + " --camera-info-topic /camera/zero_focal",
        "k: the focal lengths fx and fy must be positive, got 0 and 31");
  Fails("--bag " + bag_ + " --camera-info-topic /camera/rgb8", "carries 'sensor_msgs/msg/Image' messages");
  Fails("--bag " + bag_ + " --camera-info-topic /camera/camera_info --camera-info " +
            Write("c.yaml", "width: 40\nheight: 24\nk: [30, 0, 20, 0, 30, 12, 0, 0, 1]\n"),
        "give one calibration");
  Fails(kMrm + " --camera-info-topic /camera/camera_info", "give the recording with --bag");
}

}  // namespace
}  // namespace urdfsnap::cli_test
