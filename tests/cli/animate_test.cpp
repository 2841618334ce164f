// `urdfsnap animate` against the binary, judged by other programs: PNG sequences byte for byte
// against `urdfsnap render` of the interpolated pose, videos through the real FFmpeg tools (ffprobe
// for frame count, size and rate; ffmpeg to decode every frame) and libwebp, trajectories in every
// input format and bags written by the MCAP project's own writer (the test_bags fixture), depth,
// label, mask and keypoint sequences, clamping, the one camera of --fit and turntables,
// --print-frame, and memory that does not grow with the animation's length. Frames show a posed robot, never a blank picture.
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <regex>
#include <sstream>
#include <thread>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "image/png_reader.h"
#include "urdfsnap_process.h"
#include "video/animation_reader.h"
#include "video/ffmpeg_tools.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

// A fixed view (no --fit) and a small size, so that the expected frames are plain `render` calls.
const std::string kView = " --size 320x240 --yaw 0.9 --pitch 0.5 --distance 3.2 --focal 0,0,0.9";

// mrm's first three joints through three waypoints (seconds, radians).
const std::string kMrmCsv =
    "time,base_link__link_01,link_01__link_02,link_02__link_03\n"
    "0,0,0,0\n"
    "1,1.2,0.6,-0.9\n"
    "2,0.2,-0.5,0.7\n";
const std::vector<std::string> kMrmJoints = {"base_link__link_01", "link_01__link_02", "link_02__link_03"};
const std::vector<std::vector<double>> kMrmWaypoints = {{0, 0, 0, 0}, {1, 1.2, 0.6, -0.9}, {2, 0.2, -0.5, 0.7}};

// The position of column `joint` (1-based) of kMrmWaypoints at time t, linearly interpolated.
double MrmAt(std::size_t joint, double t) {
  for (std::size_t i = 1; i < kMrmWaypoints.size(); ++i) {
    const auto &a = kMrmWaypoints[i - 1], &b = kMrmWaypoints[i];
    if (t <= b[0]) return a[joint] + (b[joint] - a[joint]) * (t - a[0]) / (b[0] - a[0]);
  }
  return kMrmWaypoints.back()[joint];
}

// "-j NAME=VALUE ..." for mrm at time t of kMrmCsv.
std::string MrmJointsAt(double t) {
  std::ostringstream words;
  words.precision(17);
  for (std::size_t j = 0; j < kMrmJoints.size(); ++j) words << " -j " << kMrmJoints[j] << "=" << MrmAt(j + 1, t);
  return words.str();
}

// The bags' joints (tests/node/make_test_bags.mjs) on a three-link arm with a gripper finger,
// coloured boxes and cylinders so that every joint shows.
const std::string kBagArm = R"(<robot name="bag_arm">
  <material name="blue"><color rgba="0.2 0.4 0.9 1"/></material>
  <material name="orange"><color rgba="1 0.5 0.1 1"/></material>
  <link name="base"><visual><geometry><box size="0.4 0.4 0.2"/></geometry><material name="blue"/></visual></link>
  <link name="upper"><visual><origin xyz="0 0 0.4"/><geometry><cylinder radius="0.06" length="0.8"/></geometry><material name="orange"/></visual></link>
  <link name="fore"><visual><origin xyz="0 0 0.3"/><geometry><box size="0.08 0.08 0.6"/></geometry><material name="blue"/></visual></link>
  <link name="hand"><visual><origin xyz="0 0 0.1"/><geometry><box size="0.2 0.05 0.2"/></geometry><material name="orange"/></visual></link>
  <link name="finger"><visual><origin xyz="0 0 0.05"/><geometry><box size="0.03 0.03 0.1"/></geometry><material name="blue"/></visual></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><origin xyz="0 0 0.1"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/><origin xyz="0 0 0.8"/><axis xyz="0 1 0"/><limit lower="-4" upper="4" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="revolute"><parent link="fore"/><child link="hand"/><origin xyz="0 0 0.6"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="finger" type="prismatic"><parent link="hand"/><child link="finger"/><origin xyz="0.05 0 0.2"/><axis xyz="1 0 0"/><limit lower="0" upper="0.1" effort="1" velocity="1"/></joint>
</robot>
)";

// The number of pixels that are clearly not RViz's grey background or grid: the robot's.
int RobotPixels(const image::Image& frame) {
  int count = 0;
  for (std::size_t p = 0; p + 2 < frame.rgb.size(); p += 3) {
    const int r = frame.rgb[p], g = frame.rgb[p + 1], b = frame.rgb[p + 2];
    if (std::max({r, g, b}) - std::min({r, g, b}) > 40) ++count;
  }
  return count;
}

// The centre (x, y in pixels) of the pixels RobotPixels counts.
std::pair<double, double> RobotCentre(const image::Image& frame) {
  double x = 0, y = 0;
  int count = 0;
  for (std::size_t p = 0; p + 2 < frame.rgb.size(); p += 3) {
    const int r = frame.rgb[p], g = frame.rgb[p + 1], b = frame.rgb[p + 2];
    if (std::max({r, g, b}) - std::min({r, g, b}) <= 40) continue;
    const std::size_t pixel = p / 3, width = static_cast<std::size_t>(frame.width);
    x += static_cast<double>(pixel % width);
    y += static_cast<double>(pixel / width);
    ++count;
  }
  return count > 0 ? std::pair(x / count, y / count) : std::pair(0.0, 0.0);
}

// How far apart two centres are, in pixels.
double Apart(std::pair<double, double> a, std::pair<double, double> b) {
  return std::hypot(a.first - b.first, a.second - b.second);
}

class AnimateTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    mrm_ = Write("mrm.urdf", ReadBytes(kMrm));
    csv_ = Write("wave.csv", kMrmCsv);
  }

  // The words --print-frame gives for frame k of `animation` (animate's arguments without -o).
  std::string FrameWords(const std::string& animation, std::int64_t k) {
    std::string words = Ok("animate " + animation + " --print-frame " + std::to_string(k));
    while (!words.empty() && words.back() == '\n') words.pop_back();
    return words;
  }

  std::string mrm_, csv_;
};

TEST_F(AnimateTest, PngFramesAreRenderOfTheInterpolatedPoseAtKOverFps) {
  // T = 2 s at 4 frames/s: frames k = 0 .. 8 at t = k / 4
  Ok("animate " + mrm_ + " --trajectory " + csv_ + " --fps 4" + kView + " -o " + Path("f/%03d.png"));
  ASSERT_TRUE(fs::exists(Path("f/008.png")));
  EXPECT_FALSE(fs::exists(Path("f/009.png")));
  std::vector<std::string> frames;
  for (int k = 0; k <= 8; ++k) {
    char name[16];
    std::snprintf(name, sizeof name, "f/%03d.png", k);
    frames.push_back(ReadBytes(Path(name)));
    const image::Image frame = image::DecodePng(frames.back(), name);
    EXPECT_GT(RobotPixels(frame), 2000) << "frame " << k << " shows no robot";
    EXPECT_EQ(frames.back(), Render(mrm_ + kView + MrmJointsAt(k / 4.0))) << "frame " << k;
  }
  EXPECT_NE(frames[0], frames[4]);
  EXPECT_NE(frames[4], frames[8]);
}

TEST_F(AnimateTest, SpeedAndDurationSetTheFrameCountAndTheLastPoseHolds) {
  // --speed 2: T = 1 s, frames at trajectory times 0, 0.5, 1, 1.5, 2
  Ok("animate " + mrm_ + " --trajectory " + csv_ + " --fps 2 --speed 2" + kView + " -o " + Path("fast/%d.png"));
  EXPECT_TRUE(fs::exists(Path("fast/2.png")));
  EXPECT_FALSE(fs::exists(Path("fast/3.png")));
  EXPECT_EQ(ReadBytes(Path("fast/1.png")), Render(mrm_ + kView + MrmJointsAt(1.0)));
  // --duration 3 beyond T = 2: the frames after the end show the last pose
  Ok("animate " + mrm_ + " --trajectory " + csv_ + " --fps 2 --duration 3" + kView + " -o " + Path("long/%d.png"));
  EXPECT_TRUE(fs::exists(Path("long/6.png")));
  EXPECT_FALSE(fs::exists(Path("long/7.png")));
  EXPECT_EQ(ReadBytes(Path("long/4.png")), ReadBytes(Path("long/6.png")));
  EXPECT_EQ(ReadBytes(Path("long/6.png")), Render(mrm_ + kView + MrmJointsAt(2.0)));
}

TEST_F(AnimateTest, PrintFrameReproducesFramesOfAFittedTurntableByteForByte) {
  const std::string animation = mrm_ + " --trajectory " + csv_ + " --fps 3 --fit --turntable --size 320x240";
  Ok("animate " + animation + " -o " + Path("t/%02d.png"));
  const std::string last = "06";  // T = 2 s at 3 frames/s
  ASSERT_TRUE(fs::exists(Path("t/" + last + ".png")));
  std::vector<std::string> seen;
  for (int k : {0, 3, 6}) {
    const std::string words = FrameWords(animation, k);
    EXPECT_NE(words.find("--distance="), std::string::npos) << words;
    const std::string frame = ReadBytes(Path("t/0" + std::to_string(k) + ".png"));
    EXPECT_EQ(frame, Render(mrm_ + " --size 320x240 " + words)) << "frame " << k << ": " << words;
    seen.push_back(words);
  }
  // one camera: the same focal point and distance in every frame, the yaw turning by 2 pi k / 7
  const std::regex fitted("--distance=(\\S+) --focal=(\\S+)");
  std::smatch first, other;
  ASSERT_TRUE(std::regex_search(seen[0], first, fitted));
  ASSERT_TRUE(std::regex_search(seen[2], other, fitted));
  EXPECT_EQ(first.str(), other.str());
  const std::regex yaw("--yaw=(\\S+)");
  std::smatch y0, y3;
  ASSERT_TRUE(std::regex_search(seen[0], y0, yaw));
  ASSERT_TRUE(std::regex_search(seen[1], y3, yaw));
  EXPECT_NEAR(std::stod(y3[1]) - std::stod(y0[1]), 2 * std::numbers::pi * 3 / 7, 1e-12);
}

TEST_F(AnimateTest, FitFramesEveryFrameWithOneCamera) {
  // mrm swinging far to one side late in the motion: a camera fitted to frame 0 alone would cut it
  const std::string swing = Write("swing.csv", "time,link_01__link_02\n0,0\n1,1.5\n");
  const std::string animation = mrm_ + " --trajectory " + swing + " --fps 2 --fit --size 320x240";
  Ok("animate " + animation + " -o " + Path("s/%d.png"));
  EXPECT_EQ(FrameWords(animation, 0).substr(0, FrameWords(animation, 0).find(" -j")),
            FrameWords(animation, 2).substr(0, FrameWords(animation, 2).find(" -j")));
  // the swung-out frame is fitted: the robot reaches near the image's edge but is not cut there
  const image::Image last = image::ReadPng(Path("s/2.png"));
  EXPECT_GT(RobotPixels(last), 2000);
  const std::string single = Render(mrm_ + " --size 320x240 --fit -j link_01__link_02=0");
  EXPECT_NE(ReadBytes(Path("s/0.png")), single) << "frame 0 must use the camera of all frames";
}

TEST_F(AnimateTest, StillTurntableLastsTheDurationAndTurnsOnce) {
  Ok("animate " + mrm_ + " --turntable --duration 2 --fps 4 -j link_01__link_02=0.8" + kView + " -o " +
     Path("spin/%d.png"));
  EXPECT_TRUE(fs::exists(Path("spin/8.png")));
  EXPECT_FALSE(fs::exists(Path("spin/9.png")));
  // frame k looks from yaw 0.9 + 2 pi k / 9
  const std::string view = " --size 320x240 --pitch 0.5 --distance 3.2 --focal 0,0,0.9";
  std::ostringstream yaw;
  yaw.precision(17);
  yaw << 0.9 + 2 * std::numbers::pi * 3 / 9;
  EXPECT_EQ(ReadBytes(Path("spin/3.png")),
            Render(mrm_ + view + " --yaw " + yaw.str() + " -j link_01__link_02=0.8"));
  EXPECT_NE(ReadBytes(Path("spin/0.png")), ReadBytes(Path("spin/3.png")));
}

struct VideoCase {
  const char* file;
  const char* codec;
  // tolerances per channel value for decoded frames against render's PNG (see the instantiation)
  double max_mean;
  int max_percentile_99;
};

void PrintTo(const VideoCase& format, std::ostream* out) { *out << format.file; }

class AnimateVideoTest : public AnimateTest, public ::testing::WithParamInterface<VideoCase> {};

// Every decoded frame of FILE, with the time each ends (ms).
std::vector<std::pair<image::Image, double>> ReadAll(const std::string& file) {
  std::vector<std::pair<image::Image, double>> frames;
  const auto reader = video::OpenAnimationReader(file);
  image::Image frame;
  double end = 0;
  while (reader->Next(frame, end)) frames.emplace_back(frame, end);
  return frames;
}

TEST_P(AnimateVideoTest, DecodesToRenderOfEachFrameAtTheRateAsked) {
  const VideoCase& format = GetParam();
  const std::string out = Path(format.file);
  // T = 2 s at 5 frames/s: 11 frames
  Ok("animate " + mrm_ + " --trajectory " + csv_ + " --fps 5" + kView + " -o " + out);
  constexpr int kFrames = 11;
  std::vector<image::Image> decoded;
  if (format.codec == std::string("webp")) {
    // FFmpeg 5 reads no animated WebP: libwebp's decoder, each frame shown for 200 ms
    const auto frames = ReadAll(out);
    ASSERT_FALSE(frames.empty());
    EXPECT_NEAR(frames.back().second, kFrames * 200.0, 1);
    for (const auto& [frame, end] : frames) decoded.push_back(frame);
  } else {
    const test::ProbedVideo video = test::Probe(out);
    EXPECT_EQ(video.codec, format.codec);
    EXPECT_EQ(video.width, 320);
    EXPECT_EQ(video.height, 240);
    EXPECT_EQ(video.frame_rate, "5/1");
    EXPECT_EQ(video.frames, kFrames);
    decoded = test::DecodeFrames(out, 320, 240);
  }
  ASSERT_EQ(decoded.size(), std::size_t{kFrames});
  std::vector<image::Image> expected;
  for (int k = 0; k < kFrames; ++k) {
    expected.push_back(image::DecodePng(Render(mrm_ + kView + MrmJointsAt(k / 5.0)), "render"));
    EXPECT_GT(RobotPixels(expected.back()), 2000);
    const test::FrameDifference difference = test::Compare(decoded[k], expected.back());
    EXPECT_LE(difference.mean, format.max_mean) << "frame " << k;
    EXPECT_LE(difference.percentile_99, format.max_percentile_99) << "frame " << k;
  }
  // frames far apart in the motion are told apart beyond those tolerances
  const test::FrameDifference apart = test::Compare(decoded[0], expected[5]);
  EXPECT_GT(apart.percentile_99, 2 * format.max_percentile_99);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, AnimateVideoTest,
    ::testing::Values(
        // measured on these frames (the worst frame), tolerances about 1.5 times that: H.264 at
        // CRF 20 with 4:2:0 chroma: mean 1.3, 99th percentile 11; VP9: 1.5, 13; lossy WebP: 1.1,
        // 12; GIF (one dithered palette; these frames have few colours): 0.01, 0
        VideoCase{"wave.mp4", "h264", 2.0, 17}, VideoCase{"wave.webm", "vp9", 2.2, 20},
        VideoCase{"wave.gif", "gif", 0.5, 8}, VideoCase{"wave.webp", "webp", 1.7, 18}),
    [](const auto& info) {
      const std::string file = info.param.file;
      return file.substr(file.find('.') + 1);
    });

// The motion of kMrmCsv in each input format urdfsnap reads.
const std::map<std::string, std::string> kMrmFormats = {
    {"plan.yaml",  // trajectory_msgs/JointTrajectory as `ros2 topic echo` prints it
     "header:\n  stamp:\n    sec: 0\n    nanosec: 0\n  frame_id: ''\n"
     "joint_names:\n- base_link__link_01\n- link_01__link_02\n- link_02__link_03\n"
     "points:\n"
     "- positions: [0.0, 0.0, 0.0]\n  time_from_start:\n    sec: 0\n    nanosec: 0\n"
     "- positions: [1.2, 0.6, -0.9]\n  time_from_start:\n    sec: 1\n    nanosec: 0\n"
     "- positions: [0.2, -0.5, 0.7]\n  time_from_start:\n    sec: 2\n    nanosec: 0\n---\n"},
    {"plan.json",  // the same as JSON, times in seconds
     R"({"joint_names": ["base_link__link_01", "link_01__link_02", "link_02__link_03"],
         "points": [{"positions": [0, 0, 0], "time_from_start": 0},
                    {"positions": [1.2, 0.6, -0.9], "time_from_start": {"sec": 1, "nanosec": 0}},
                    {"positions": [0.2, -0.5, 0.7], "time_from_start": 2.0}]})"},
    {"moveit.yaml",  // a MoveIt DisplayTrajectory holding one RobotTrajectory
     "model_id: mrm\ntrajectory:\n- joint_trajectory:\n"
     "    joint_names: [base_link__link_01, link_01__link_02, link_02__link_03]\n"
     "    points:\n"
     "    - {positions: [0, 0, 0], time_from_start: {sec: 0, nanosec: 0}}\n"
     "    - {positions: [1.2, 0.6, -0.9], time_from_start: {sec: 1, nanosec: 0}}\n"
     "    - {positions: [0.2, -0.5, 0.7], time_from_start: {sec: 2, nanosec: 0}}\n"},
    {"states.yaml",  // sensor_msgs/JointState messages as `ros2 topic echo /joint_states` prints them
     "header:\n  stamp:\n    sec: 1700000100\n    nanosec: 500000000\n  frame_id: ''\n"
     "name:\n- base_link__link_01\n- link_01__link_02\n- link_02__link_03\n"
     "position:\n- 0.0\n- 0.0\n- 0.0\nvelocity: []\neffort: []\n---\n"
     "header:\n  stamp:\n    sec: 1700000101\n    nanosec: 500000000\n  frame_id: ''\n"
     "name:\n- base_link__link_01\n- link_01__link_02\n- link_02__link_03\n"
     "position:\n- 1.2\n- 0.6\n- -0.9\nvelocity: []\neffort: []\n---\n"
     "header:\n  stamp:\n    sec: 1700000102\n    nanosec: 500000000\n  frame_id: ''\n"
     "name:\n- base_link__link_01\n- link_01__link_02\n- link_02__link_03\n"
     "position:\n- 0.2\n- -0.5\n- 0.7\nvelocity: []\neffort: []\n---\n"},
};

TEST_F(AnimateTest, EveryTextFormatGivesTheFramesOfTheCsvTable) {
  Ok("animate " + mrm_ + " --trajectory " + csv_ + " --fps 4" + kView + " -o " + Path("csv/%d.png"));
  for (const auto& [name, text] : kMrmFormats) {
    const std::string folder = name.substr(0, name.find('.')) + "_" + name.substr(name.find('.') + 1);
    Ok("animate " + mrm_ + " --trajectory " + Write(name, text) + " --fps 4" + kView + " -o " + Path(folder + "/%d.png"));
    for (int k = 0; k <= 8; ++k) {
      const std::string frame = "/" + std::to_string(k) + ".png";
      EXPECT_EQ(ReadBytes(Path(folder + frame)), ReadBytes(Path("csv" + frame))) << name << " frame " << k;
    }
    EXPECT_FALSE(fs::exists(Path(folder + "/9.png"))) << name;
  }
}

TEST_F(AnimateTest, LeavesACoreToTheEncoderAndDrawsTheSameFrames) {
  // llvmpipe rasterises on the cores the encoder leaves (--verbose says so), unless the user set
  // LP_NUM_THREADS; the frames are the same byte for byte either way
  const std::string animate = "animate " + mrm_ + " --trajectory " + csv_ + " --fps 4" + kView + " --verbose -o ";
  const Result ours = RunUrdfsnap(animate + Path("ours/%d.png"));
  ASSERT_EQ(ours.status, 0) << ours.output;
  EXPECT_NE(ours.output.find("urdfsnap: LP_NUM_THREADS="), std::string::npos) << ours.output;
  EXPECT_NE(ours.output.find(" left to encoding\n"), std::string::npos) << ours.output;
  const Result users = RunUrdfsnap(animate + Path("users/%d.png"), "LP_NUM_THREADS=4");
  ASSERT_EQ(users.status, 0) << users.output;
  EXPECT_EQ(users.output.find("LP_NUM_THREADS"), std::string::npos) << users.output;
  for (int k = 0; k <= 8; ++k) {
    const std::string frame = "/" + std::to_string(k) + ".png";
    EXPECT_EQ(ReadBytes(Path("ours" + frame)), ReadBytes(Path("users" + frame))) << k;
  }
}

TEST_F(AnimateTest, TrajectoryFromAPipeAndTheExampleTrajectories) {
  // `ros2 topic echo ... | urdfsnap animate --trajectory /dev/stdin`: a pipe is read once
  const std::string fifo = Path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << kMrmFormats.at("states.yaml"); });
  Ok("animate " + mrm_ + " --trajectory /dev/stdin --fps 4" + kView + " -o " + Path("piped/%d.png") + " < " + fifo);
  writer.join();
  EXPECT_EQ(ReadBytes(Path("piped/8.png")), Render(mrm_ + kView + MrmJointsAt(2.0)));
  // the README's example trajectory, as JointTrajectory YAML and as CSV: the same motion
  const std::string examples = (kSource / "examples/trajectories/").string();
  Ok("animate " + mrm_ + " --trajectory " + examples + "mrm_wave.yaml --fps 2" + kView + " -o " + Path("yaml/%d.png"));
  Ok("animate " + mrm_ + " --trajectory " + examples + "mrm_wave.csv --fps 2" + kView + " -o " + Path("csv/%d.png"));
  for (int k = 0; k <= 8; ++k) {
    const std::string frame = "/" + std::to_string(k) + ".png";
    EXPECT_EQ(ReadBytes(Path("yaml" + frame)), ReadBytes(Path("csv" + frame))) << k;
  }
  EXPECT_FALSE(fs::exists(Path("yaml/9.png")));
}

TEST_F(AnimateTest, BagsFromTheMcapWriterGiveTheRecordedMotion) {
  const std::string arm = Write("arm.urdf", kBagArm);
  // from the side, across the shoulder's and elbow's axis
  const std::string view = " --size 320x240 --yaw -1.5708 --pitch 0.25 --distance 3.5 --focal 0,0,0.3";
  // 200 messages 10 ms apart: T = 1.99 s, 20 frames at 10 frames/s; frame k: shoulder = 0.1 k,
  // elbow = -0.2 k (test_bags.h)
  Ok("animate " + arm + " --trajectory " + test::TestBag("joint_states_zstd.mcap") + " --fps 10" + view +
     " -o " + Path("zstd/%02d.png"));
  ASSERT_TRUE(fs::exists(Path("zstd/19.png")));
  EXPECT_FALSE(fs::exists(Path("zstd/20.png")));
  for (int k : {0, 7, 19}) {
    const std::string name = Path("zstd/" + std::string(k < 10 ? "0" : "") + std::to_string(k) + ".png");
    std::ostringstream joints;
    joints.precision(17);
    joints << " -j shoulder=" << test::BagShoulder(10 * k) << " -j elbow=" << test::BagElbow(10 * k)
           << " -j wrist=" << test::kBagWrist;
    const image::Image expected = image::DecodePng(Render(arm + view + joints.str()), "render");
    const image::Image actual = image::ReadPng(name);
    EXPECT_GT(RobotPixels(actual), 800) << name;
    // interpolation may land an ulp away from the decimal value: a picture within a few pixels
    const test::FrameDifference difference = test::Compare(actual, expected);
    EXPECT_LE(difference.max, 64) << name;
    EXPECT_LE(difference.mean, 0.05) << name;
  }
  // the other compressions, an unchunked bag, rosbag2 folders of SQLite and compressed MCAP files
  // (split in two) and a rosbag2 folder of eleven files: the same frames
  for (const std::string bag : {"joint_states_lz4.mcap", "joint_states_none.mcap", "joint_states_unchunked.mcap",
                                "rosbag2_sqlite", "rosbag2_mcap_message_zstd"}) {
    Ok("animate " + arm + " --trajectory " + test::TestBag(bag) + " --fps 10" + view + " -o " + Path(bag + "/%02d.png"));
    for (int k = 0; k < 20; k += 6) {
      const std::string frame = "/" + std::string(k < 10 ? "0" : "") + std::to_string(k) + ".png";
      EXPECT_EQ(ReadBytes(Path(bag + frame)), ReadBytes(Path("zstd" + frame))) << bag << frame;
    }
  }
  // the split bag holds messages 0 .. 54: 0.54 s, 6 frames, the same poses as the first bag's frames
  Ok("animate " + arm + " --trajectory " + test::TestBag("split_bag") + " --fps 10" + view + " -o " +
     Path("split/%02d.png"));
  EXPECT_TRUE(fs::exists(Path("split/05.png")));
  EXPECT_FALSE(fs::exists(Path("split/06.png")));
  EXPECT_EQ(ReadBytes(Path("split/05.png")), ReadBytes(Path("zstd/05.png")));
}

TEST_F(AnimateTest, StartAndEndPlayPartOfABagInSecondsOrStamps) {
  const std::string arm = Write("arm.urdf", kBagArm);
  const std::string view = " --size 160x120 --yaw -1.5708 --pitch 0.25 --distance 3.5 --focal 0,0,0.3";
  const std::string bag = " --trajectory " + test::TestBag("joint_states_zstd.mcap") + " --fps 10" + view;
  Ok("animate " + arm + bag + " -o " + Path("all/%02d.png"));
  // from 0.5 s after the first stamp to the stamp 1 s after it: 6 frames, frame k at 0.5 + k / 10 s
  Ok("animate " + arm + bag + " --start 0.5 --end 1700000001 -o " + Path("part/%02d.png"));
  EXPECT_TRUE(fs::exists(Path("part/05.png")));
  EXPECT_FALSE(fs::exists(Path("part/06.png")));
  EXPECT_EQ(ReadBytes(Path("part/00.png")), ReadBytes(Path("all/05.png")));
  EXPECT_EQ(ReadBytes(Path("part/05.png")), ReadBytes(Path("all/10.png")));
  const Result late = RunUrdfsnap("animate " + arm + bag + " --start 5 -o " + Path("late/%02d.png"));
  EXPECT_EQ(late.status, 2);
  EXPECT_NE(late.output.find("--start 5 s is outside"), std::string::npos) << late.output;
}

TEST_F(AnimateTest, ABagAloneIsTheModelAndTheMotion) {
  // rover_loop.mcap recorded the rover's description on /robot_description: no MODEL needed
  const std::string rover = test::TestBag("rover_loop.mcap") + " --fps 2 --end 1 --size 160x120 --yaw 0.8 "
                            "--pitch 0.5 --distance 2.5 --focal 0,0,0.2";
  Ok("animate " + rover + " -o " + Path("rover/%d.png"));
  ASSERT_TRUE(fs::exists(Path("rover/2.png")));
  // frame 2 (t = 1 s) is the sample model with the wheels and head as recorded then
  EXPECT_EQ(ReadBytes(Path("rover/2.png")),
            Render((kSource / "models/rover_description/urdf/rover.urdf").string() + " --size 160x120 " +
                   FrameWords(rover, 2)));
  // a bag without a description, and one whose description is no URDF
  const Result none = RunUrdfsnap("animate " + test::TestBag("joint_states_zstd.mcap") + " -o " + Path("none.gif"));
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.output.find("joint_states_zstd.mcap: no robot description: no message on '/robot_description'; "
                             "its topics are: /camera/image_raw"),
            std::string::npos)
      << none.output;
  const Result junk = RunUrdfsnap("animate " + test::TestBag("description_junk.mcap") + " -o " + Path("junk.gif"));
  EXPECT_EQ(junk.status, 2);
  EXPECT_NE(junk.output.find("description_junk.mcap: '/robot_description'"), std::string::npos) << junk.output;
  EXPECT_EQ(junk.output.find("robot_description.urdf"), std::string::npos) << junk.output;
  EXPECT_FALSE(fs::exists(Path("none.gif")) || fs::exists(Path("junk.gif")));
}

TEST_F(AnimateTest, AFixedFrameOutsideTheRobotPlacesItWhereTfSays) {
  // rover_loop.mcap drives a loop of 1 m radius about (0, 1) in 8 s; seen from above its centre
  const std::string rover = test::TestBag("rover_loop.mcap") +
                            " --fps 1 --size 160x120 --no-grid --yaw 0 --pitch 1.5 --distance 6 --focal 0,1,0";
  Ok("animate " + rover + " --fixed-frame odom -o " + Path("odom/%d.png"));
  Ok("animate " + rover + " -o " + Path("base/%d.png"));
  // at 0 s odom and base_link coincide
  EXPECT_EQ(ReadBytes(Path("odom/0.png")), ReadBytes(Path("base/0.png")));
  // at 4 s the rover is across the loop, 2 m (about 48 pixels) from where it started; in its own
  // frame it stays where it was
  const auto centre = [&](const std::string& frame) { return RobotCentre(image::ReadPng(Path(frame))); };
  EXPECT_GT(Apart(centre("odom/4.png"), centre("odom/0.png")), 35);
  EXPECT_LT(Apart(centre("base/4.png"), centre("base/0.png")), 5);
  EXPECT_GT(RobotPixels(image::ReadPng(Path("odom/4.png"))), 100);
  // a frame TF does not connect to the robot
  const Result other = RunUrdfsnap("animate " + rover + " --fixed-frame map -o " + Path("map/%d.png"));
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.output.find("--fixed-frame 'map': neither a link of the robot nor a frame"), std::string::npos)
      << other.output;
}

TEST_F(AnimateTest, ACameraFrameOutsideTheRobotFollowsTheBagsTf) {
  // a camera fixed in odom 6 m above the rover's loop centre (0, 1), looking down (x along +x, y
  // along -y): 180° about x. f = 60 / tan(22.5°) at 160x120
  const std::string camera = " --camera-frame odom --camera-pose 0,1,6,1,0,0,0 --size 160x120 --no-grid";
  const std::string rover = test::TestBag("rover_loop.mcap");
  Ok("animate " + rover + " --fps 1" + camera + " -o " + Path("c/%d.png") + " --keypoints " + Path("k/%d.json"));
  const double f = 60 / std::tan(std::numbers::pi / 8);
  for (const auto& [k, y] : {std::pair{0, 0.0}, std::pair{4, 2.0}}) {
    // base_link at (0, y, 0) in odom: 6 m below the camera, 1 - y metres along the image's v
    const nlohmann::json keypoints = nlohmann::json::parse(ReadBytes(Path("k/" + std::to_string(k) + ".json")));
    const nlohmann::json& base = keypoints["frames"][0];
    EXPECT_EQ(base["name"], "base_link");
    EXPECT_NEAR(base["u"].get<double>(), 79.5, 1e-6) << k;
    EXPECT_NEAR(base["v"].get<double>(), 59.5 + f * (1 - y) / 6, 1e-6) << k;
    EXPECT_NEAR(base["depth"].get<double>(), 6, 1e-9) << k;
    EXPECT_GT(RobotPixels(image::ReadPng(Path("c/" + std::to_string(k) + ".png"))), 100) << k;
  }
  EXPECT_GT(Apart(RobotCentre(image::ReadPng(Path("c/0.png"))), RobotCentre(image::ReadPng(Path("c/4.png")))), 35);
  const Result words = RunUrdfsnap("animate " + rover + camera + " --print-frame 1");
  EXPECT_EQ(words.output, "urdfsnap: error: --print-frame: the camera is placed by TF from 'odom', which `render` "
                          "draws with --bag " + rover + " --at SECONDS\n");
  // a frame TF does not connect to the robot
  const Result other = RunUrdfsnap("animate " + rover + " --camera-frame map -o " + Path("map/%d.png"));
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.output.find("--camera-frame 'map': neither a link of the robot nor a frame"), std::string::npos)
      << other.output;
}

TEST_F(AnimateTest, BagWithTwoPublishersMovesTheArmAndTheGripper) {
  const std::string arm = Write("arm.urdf", kBagArm);
  const std::string animation = arm + " --trajectory " + test::TestBag("two_publishers.mcap") + " --fps 10";
  // message i: finger = 0.001 i every other message, at 10 ms per message: frame 9 at 0.9 s
  const std::string words = FrameWords(animation, 9);
  EXPECT_NE(words.find("-j finger=0.09"), std::string::npos) << words;
  EXPECT_NE(words.find("-j shoulder=0.9"), std::string::npos) << words;
}

TEST_F(AnimateTest, DepthAndLabelSequencesAreRendersOfTheSameFrames) {
  const std::string animation = mrm_ + " --trajectory " + csv_ + " --fps 2 --fit --size 320x240";
  Ok("animate " + animation + " -o " + Path("c/%d.png") + " --depth " + Path("d/%d.png") + " --labels " +
     Path("l/%d.png"));
  Ok("animate " + animation + " -o " + Path("v.mp4") + " --depth " + Path("n/%d.npy"));
  for (int k : {1, 4}) {
    const std::string words = FrameWords(animation, k);
    const std::string n = std::to_string(k);
    Ok("render " + mrm_ + " --size 320x240 " + words + " -o " + Path("r.png") + " --depth " + Path("r_d.png") +
       " --labels " + Path("r_l.png"));
    Ok("render " + mrm_ + " --size 320x240 " + words + " -o " + Path("r.png") + " --depth " + Path("r_d.npy"));
    EXPECT_EQ(ReadBytes(Path("c/" + n + ".png")), ReadBytes(Path("r.png"))) << k;
    EXPECT_EQ(ReadBytes(Path("d/" + n + ".png")), ReadBytes(Path("r_d.png"))) << k;
    EXPECT_EQ(ReadBytes(Path("l/" + n + ".png")), ReadBytes(Path("r_l.png"))) << k;
    EXPECT_EQ(ReadBytes(Path("n/" + n + ".npy")), ReadBytes(Path("r_d.npy"))) << k;
  }
  EXPECT_FALSE(fs::exists(Path("d/5.png")));
  // the link names once for the sequence, as render writes them beside its label image
  EXPECT_EQ(ReadBytes(Path("l/labels.json")), ReadBytes(Path("r_l.json")));
  EXPECT_FALSE(fs::exists(Path("l/0.json")));
}

TEST_F(AnimateTest, MaskAndKeypointSequencesAreWhatRenderWritesForEachFrame) {
  // the orbit view fitted over the motion, and a calibrated camera with its lens
  const std::string camera = " --camera-info " + (kSource / "tests/data/camera/ost.yaml").string() +
                             " --camera-pose 5,0.05,1,-0.5,-0.5,0.5,0.5 --distort";
  for (const std::string& view : {std::string(" --fit --size 240x180"), camera}) {
    const std::string animation = mrm_ + " --trajectory " + csv_ + " --fps 2" + view;
    Ok("animate " + animation + " -o " + Path("c/%d.png") + " --mask " + Path("m/%d.png") + " --mask-dilate 2" +
       " --keypoints " + Path("k/%02d.json"));
    EXPECT_FALSE(fs::exists(Path("m/5.png")));
    for (int k : {1, 4}) {
      // the words give the joints (and the orbit view); a camera is render's own option
      const std::string words = (view == camera ? camera : " --size 240x180") + " " + FrameWords(animation, k);
      Ok("render " + mrm_ + " " + words + " -o " + Path("r.png") + " --mask " + Path("r_m.png") +
         " --mask-dilate 2 --keypoints " + Path("r_k.json"));
      const std::string n = std::to_string(k);
      EXPECT_EQ(ReadBytes(Path("c/" + n + ".png")), ReadBytes(Path("r.png"))) << view << k;
      EXPECT_EQ(ReadBytes(Path("m/" + n + ".png")), ReadBytes(Path("r_m.png"))) << view << k;
      EXPECT_EQ(ReadBytes(Path("k/0" + n + ".json")), ReadBytes(Path("r_k.json"))) << view << k;
      EXPECT_GT(RobotPixels(image::ReadPng(Path("c/" + n + ".png"))), 500) << view << k;
    }
    fs::remove_all(Path("c"));
    fs::remove_all(Path("m"));
    fs::remove_all(Path("k"));
  }
  // the sequences' names are checked before anything is drawn
  const Result bad = RunUrdfsnap("animate " + mrm_ + " --trajectory " + csv_ + " -o " + Path("c/%d.png") +
                                 " --keypoints " + Path("k/%d.txt"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--keypoints '" + Path("k/%d.txt") + "': expected .json files"), std::string::npos)
      << bad.output;
  const Result one = RunUrdfsnap("animate " + mrm_ + " --trajectory " + csv_ + " -o " + Path("c/%d.png") +
                                 " --mask " + Path("mask.png"));
  EXPECT_EQ(one.status, 2);
  EXPECT_NE(one.output.find("expected a pattern with the frame number, such as frames/%05d.png"), std::string::npos)
      << one.output;
  EXPECT_FALSE(fs::exists(Path("c")));
}

TEST_F(AnimateTest, JointsBeyondTheirLimitsAreDrawnAsRecordedWithOneWarningPerJoint) {
  const std::string far = Write("far.csv", "time,base_link__link_01,link_01__link_02\n0,0,0\n1,9,-4\n2,-9,4\n");
  const Result result = RunUrdfsnap("animate " + mrm_ + " --trajectory " + far + " --fps 10" + kView + " -o " +
                                    Path("far/%02d.png"));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("urdfsnap: warning: joint 'link_01__link_02': " + far +
                               " takes it outside its limits"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("drawn as recorded (--clamp clamps it)"), std::string::npos) << result.output;
  // frame 10 (t = 1 s) shows the values themselves; --print-frame says so with --no-clamp
  EXPECT_EQ(ReadBytes(Path("far/10.png")),
            Render(mrm_ + kView + " --no-clamp -j base_link__link_01=9 -j link_01__link_02=-4"));
  const Result words = RunUrdfsnap("animate " + mrm_ + " --trajectory " + far + " --fps 10 --print-frame 10" + kView);
  ASSERT_EQ(words.status, 0) << words.output;
  EXPECT_NE(words.output.find("--no-clamp"), std::string::npos) << words.output;
}

TEST_F(AnimateTest, JointsTheModelLacksAreIgnoredWithOneWarning) {
  // a gripper on the same topic as the arm: robot_state_publisher ignores what the model lacks
  const std::string extra = Write("extra.csv", "time,base_link__link_01,gripper_left,gripper_right\n0,0,0,0\n1,1,0.1,0.1\n");
  const Result result = RunUrdfsnap("animate " + mrm_ + " --trajectory " + extra + " --fps 2" + kView + " -o " +
                                    Path("extra/%d.png"));
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find(extra + ": joints robot 'mrm' does not have are ignored: 'gripper_left', "
                                       "'gripper_right' (--strict-joints stops instead)"),
            std::string::npos)
      << result.output;
  EXPECT_EQ(ReadBytes(Path("extra/2.png")), Render(mrm_ + kView + " -j base_link__link_01=1"));
  const Result strict = RunUrdfsnap("animate " + mrm_ + " --trajectory " + extra + " --strict-joints --fps 2" +
                                    kView + " -o " + Path("strict/%d.png"));
  EXPECT_EQ(strict.status, 2);
  EXPECT_NE(strict.output.find(extra + ":1: robot 'mrm' has no joint 'gripper_left'"), std::string::npos)
      << strict.output;
  EXPECT_FALSE(fs::exists(Path("strict")));
}

TEST_F(AnimateTest, ClampKeepsJointsWithinTheirLimitsWithOneWarningPerJoint) {
  // mrm's revolute joints reach about +-3.14 (link_01__link_02: +-1.57): two joints leave them in
  // most frames
  const std::string far = Write("far.csv", "time,base_link__link_01,link_01__link_02\n0,0,0\n1,9,-4\n2,-9,4\n");
  const Result result = RunUrdfsnap("animate " + mrm_ + " --trajectory " + far + " --clamp --fps 10" + kView +
                                    " -o " + Path("far/%02d.png"));
  ASSERT_EQ(result.status, 0) << result.output;
  std::istringstream lines(result.output);
  std::vector<std::string> warnings;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("wrote ", 0) != 0) warnings.push_back(line);   // not the summary line
  }
  ASSERT_EQ(warnings.size(), 2u) << result.output;
  EXPECT_NE(warnings[0].find("urdfsnap: warning: joint 'base_link__link_01'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("joint 'link_01__link_02'"), std::string::npos) << warnings[1];
  EXPECT_NE(warnings[1].find("far.csv"), std::string::npos) << warnings[1];
  // frame 10 (t = 1 s) shows the joints at their limits, as render clamps -j values
  const Result clamped = RunUrdfsnap("render " + mrm_ + kView + " -j base_link__link_01=9 -j link_01__link_02=-4 -o " +
                                     Path("clamped.png"));
  ASSERT_EQ(clamped.status, 0) << clamped.output;
  EXPECT_EQ(ReadBytes(Path("far/10.png")), ReadBytes(Path("clamped.png")));
}

TEST_F(AnimateTest, JointsTheTrajectoryDoesNotNameTakeJointsAndJ) {
  const std::string pose = Write("pose.yaml", "link_03__link_04: 1.0\nlink_04__link_05: -0.7\n");
  Ok("animate " + mrm_ + " --trajectory " + csv_ + " --fps 1 --joints " + pose + " -j link_04__link_05=0.4" + kView +
     " -o " + Path("p/%d.png"));
  EXPECT_EQ(ReadBytes(Path("p/1.png")),
            Render(mrm_ + kView + MrmJointsAt(1.0) + " -j link_03__link_04=1 -j link_04__link_05=0.4"));
}

TEST_F(AnimateTest, OnlyASummaryLineWhenItIsNoTerminalAndNothingLeftWhenStrictStops) {
  const Result piped = RunUrdfsnap("animate " + mrm_ + " --trajectory " + csv_ + " --fps 2" + kView + " -o " +
                                   Path("q.gif"));
  EXPECT_EQ(piped.status, 0);
  // no progress bar into a pipe, but a CI log says what was made
  EXPECT_TRUE(std::regex_match(piped.output, std::regex("wrote .*q\\.gif \\([0-9.]+ kB\\): 5 frames in [0-9.]+ s "
                                                        "\\([0-9.]+ frames/s\\)\n")))
      << piped.output;
  const Result quiet = RunUrdfsnap("animate " + mrm_ + " --trajectory " + csv_ + " --fps 2" + kView + " -o " +
                                   Path("q2.gif") + " --quiet");
  EXPECT_EQ(quiet.output, "") << "--quiet: nothing";
  // --strict turns the GIF frame-delay advice into an error after the outputs were opened: no
  // file and no folder made for it stays
  const Result strict = RunUrdfsnap("--strict animate " + mrm_ + " --trajectory " + csv_ + " --fps 60" + kView +
                                    " -o " + Path("new/deeper/fast.gif") + " --depth " + Path("depth/%d.png"));
  EXPECT_EQ(strict.status, 2) << strict.output;
  EXPECT_NE(strict.output.find("urdfsnap: error:"), std::string::npos) << strict.output;
  EXPECT_FALSE(fs::exists(Path("new")));
  EXPECT_FALSE(fs::exists(Path("depth")));
}

TEST_F(AnimateTest, PrintFrameOutsideTheAnimationIsAnError) {
  const Result result = RunUrdfsnap("animate " + mrm_ + " --trajectory " + csv_ + " --fps 2 --print-frame 5");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.output.find("--print-frame '5': expected a frame number from 0 to 4"), std::string::npos)
      << result.output;
}

// Peak memory of an animation of `frames` frames at 64x48 into `file`.
long PeakMemoryKb(const std::string& model, const std::string& file, int frames) {
  const std::string duration = std::to_string(frames - 1) + " --fps 1";
  const test::ProcessResult run = test::RunUrdfsnap(
      "animate " + model + " --turntable --size 64x48 --duration " + duration + " -o " + file, 600);
  EXPECT_EQ(run.status, 0) << run.err;
  return run.peak_rss_kb;
}

TEST_F(AnimateTest, MemoryDoesNotGrowWithTheNumberOfFrames) {
  if (test::BuiltWithAddressSanitizer()) GTEST_SKIP() << "the sanitizer's own memory hides the figure";
  for (const std::string file : {"m.mp4", "m.gif"}) {
    const long short_run = PeakMemoryKb(mrm_, Path("short_" + file), 100);
    const long long_run = PeakMemoryKb(mrm_, Path("long_" + file), 10'000);
    EXPECT_LT(long_run, short_run + 8 * 1024) << file << ": " << short_run << " KB for 100 frames, " << long_run
                                              << " KB for 10,000";
    EXPECT_EQ(test::Probe(Path("long_" + file)).frames, 10'000);
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
