// `urdfsnap render --bag FILE --at SECONDS` against the binary: a still of a recording is the frame
// `animate` draws at that moment, byte for byte (joints, TF's fixed frame, TF display of the bag's
// frames, the followed frame); MODEL may be the bag, or be left out for the bag's own description;
// bad times, missing bags and frames TF does not know are one error line with nothing written.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

// rover_loop.mcap (tests/node/make_test_bags.mjs) drives a loop of 1 m radius about (0, 1) in 8 s;
// seen from above its centre.
const std::string kTopView = " --size 160x120 --yaw 0 --pitch 1.5 --distance 6 --focal 0,1,0";

class BagRenderTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
  }
  // Runs a command that must fail: exit 2, one error line naming `expected`, no output file.
  void Fails(const std::string& arguments, const std::string& expected) {
    const Result result = RunUrdfsnap(arguments + " -o " + Path("bad.png"));
    EXPECT_EQ(result.status, 2) << arguments << "\n" << result.output;
    EXPECT_NE(result.output.find("urdfsnap: error: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(expected), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(Path("bad.png")));
  }
};

// The pixels where two images of one size differ by more than a little.
struct Changed {
  int count = 0;
  double far = 0;   // the largest distance of a changed pixel from (cx, cy)
};
Changed ChangedPixels(const image::Image& a, const image::Image& b, double cx, double cy) {
  Changed changed;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::size_t p = 3 * (static_cast<std::size_t>(y) * a.width + x);
      int difference = 0;
      for (int c = 0; c < 3; ++c) difference += std::abs(a.rgb[p + c] - b.rgb[p + c]);
      if (difference <= 30) continue;
      ++changed.count;
      changed.far = std::max(changed.far, std::hypot(x - cx, y - cy));
    }
  }
  return changed;
}

// The centre of the robot's pixels (coloured, not grey) in a PNG, and how many there are.
struct Centre {
  double x = 0, y = 0;
  int pixels = 0;
};
Centre RobotCentre(const image::Image& image) {
  Centre c;
  for (int p = 0; p < image.width * image.height; ++p) {
    const auto* rgb = &image.rgb[3 * static_cast<std::size_t>(p)];
    if (std::max({rgb[0], rgb[1], rgb[2]}) - std::min({rgb[0], rgb[1], rgb[2]}) <= 40) continue;
    c.x += p % image.width;
    c.y += p / image.width;
    ++c.pixels;
  }
  if (c.pixels > 0) c.x /= c.pixels, c.y /= c.pixels;
  return c;
}

TEST_F(BagRenderTest, AStillIsTheFrameAnimateDrawsAtThatMoment) {
  const std::string bag = test::TestBag("rover_loop.mcap");
  for (const std::string& options : {std::string(" --fixed-frame odom --tf"), std::string(" --tf-scale 2 --tf")}) {
    Ok("animate " + bag + kTopView + options + " --fps 1 -o " + Path("a/%d.png"));
    // MODEL left out: the bag's description; MODEL given as the bag: the same
    EXPECT_EQ(ReadBytes(Path("a/3.png")), Render("--bag " + bag + " --at 3" + kTopView + options)) << options;
    EXPECT_EQ(ReadBytes(Path("a/0.png")), Render(bag + kTopView + options)) << options;
    // an absolute stamp: the bag starts at 1700000000 s
    EXPECT_EQ(ReadBytes(Path("a/5.png")), Render(bag + " --at 1700000005" + kTopView + options)) << options;
    // the description given as a file draws the same robot
    EXPECT_EQ(ReadBytes(Path("a/5.png")),
              Render((kSource / "models/rover_description/urdf/rover.urdf").string() + " --bag " + bag + " --at 5" +
                     kTopView + options))
        << options;
  }
}

TEST_F(BagRenderTest, ACameraInTheBagsTfIsPlacedAtTheMoment) {
  // a camera fixed in odom 6 m above the loop's centre, looking down: animate moves it per frame
  // through the bag's TF (tests/cli/animate_test.cpp); the still at 4 s is animate's frame 4 in
  // every image, byte for byte
  const std::string bag = test::TestBag("rover_loop.mcap");
  const std::string camera = " --camera-frame odom --camera-pose 0,1,6,1,0,0,0 --size 160x120 --no-grid";
  Ok("animate " + bag + camera + " --fps 1 -o " + Path("a/%d.png") + " --depth " + Path("d/%d.png") +
     " --keypoints " + Path("k/%d.json"));
  Ok("render --bag " + bag + " --at 4" + camera + " -o " + Path("still.png") + " --depth " + Path("still_d.png") +
     " --keypoints " + Path("still.json"));
  EXPECT_EQ(ReadBytes(Path("a/4.png")), ReadBytes(Path("still.png")));
  EXPECT_EQ(ReadBytes(Path("d/4.png")), ReadBytes(Path("still_d.png")));
  EXPECT_EQ(ReadBytes(Path("k/4.json")), ReadBytes(Path("still.json")));
  // the rover has moved 2 m across the picture since 0 s
  const Centre start = RobotCentre(image::DecodePng(Render("--bag " + bag + " --at 0" + camera), "start"));
  const Centre now = RobotCentre(image::ReadPng(Path("still.png")));
  ASSERT_GT(now.pixels, 100);
  EXPECT_GT(std::hypot(now.x - start.x, now.y - start.y), 35);
  Fails("render --bag " + bag + " --camera-frame map", "--camera-frame 'map': neither a link of the robot nor a frame");
}

TEST_F(BagRenderTest, TheTfDisplayShowsTheBagsFramesBesideTheRobots) {
  // at 4 s the rover is across the loop, 2 m from odom; with the TF display odom's axes and name,
  // and the arrow from base_link to it, are drawn away from the robot
  const std::string still = "--bag " + test::TestBag("rover_loop.mcap") + " --at 4 --fixed-frame odom" + kTopView;
  const image::Image plain = image::DecodePng(Render(still), "plain");
  const image::Image tf = image::DecodePng(Render(still + " --tf --no-tf-names"), "tf");
  const Centre robot = RobotCentre(plain);
  ASSERT_GT(robot.pixels, 50) << "no robot in the still";
  const Changed changed = ChangedPixels(plain, tf, robot.x, robot.y);
  EXPECT_GT(changed.count, 40);
  // 2 m is about 48 pixels in this view: odom's axes are drawn there
  EXPECT_GT(changed.far, 40);
}

TEST_F(BagRenderTest, FollowKeepsTheFocalPointOnAFrame) {
  // the rover drives a loop in odom; followed, it stays in the middle of the picture
  const std::string bag = test::TestBag("rover_loop.mcap");
  const std::string view = " --fixed-frame odom --size 160x120 --no-grid --yaw 0 --pitch 1.5 --distance 3 --focal 0,0,0";
  Ok("animate " + bag + view + " --follow base_link --fps 1 -o " + Path("follow/%d.png"));
  Ok("animate " + bag + view + " --fps 1 -o " + Path("still/%d.png"));
  for (int k : {0, 2, 4, 6}) {
    const Centre followed = RobotCentre(image::ReadPng(Path("follow/" + std::to_string(k) + ".png")));
    ASSERT_GT(followed.pixels, 50) << k;
    EXPECT_LT(std::hypot(followed.x - 80, followed.y - 60), 12) << k;
  }
  // unfollowed, at 4 s it is 2 m (about 45 pixels) from the middle
  const Centre away = RobotCentre(image::ReadPng(Path("still/4.png")));
  EXPECT_GT(std::hypot(away.x - 80, away.y - 60), 30);
  // render --bag --at draws animate's frame; --print-frame's words with the same --follow too
  EXPECT_EQ(ReadBytes(Path("follow/4.png")), Render("--bag " + bag + " --at 4 --follow base_link" + view));
  const std::string wave = Write("wave.csv", "time,base_link__link_01,link_01__link_02\n0,0,0\n1,1.2,0.6\n2,0.2,-0.5\n");
  const std::string arm = " --size 160x120 --no-grid --distance 2 --follow link_04";
  std::string words = Ok("animate " + kMrm + arm + " --trajectory " + wave + " --fps 2 --print-frame 3");
  words.erase(words.find_last_not_of('\n') + 1);
  Ok("animate " + kMrm + arm + " --trajectory " + wave + " --fps 2 -o " + Path("arm/%d.png"));
  EXPECT_EQ(ReadBytes(Path("arm/3.png")), Render(kMrm + " --size 160x120 --no-grid --follow link_04 " + words));
  EXPECT_NE(ReadBytes(Path("arm/0.png")), ReadBytes(Path("arm/3.png")));
  // a frame of the bag's TF outside the robot is followed too: in base_link's frame at 4 s (turned
  // half round, 2 m along odom's y) odom is at (0, 2, 0)
  const std::string from_base = " --size 160x120 --no-grid --yaw 0 --pitch 1.5 --distance 6";
  const Centre odom = RobotCentre(image::DecodePng(Render("--bag " + bag + " --at 4 --follow odom" + from_base), "odom"));
  const Centre there = RobotCentre(image::DecodePng(Render("--bag " + bag + " --at 4 --focal 0,2,0" + from_base), "focal"));
  ASSERT_GT(there.pixels, 50);
  EXPECT_LT(std::hypot(odom.x - there.x, odom.y - there.y), 1.5);
  Fails("render --bag " + bag + " --follow nowhere", "--follow 'nowhere': neither a link of robot");
  Fails("render " + kMrm + " --follow odom", "--follow 'odom' is not a link of robot 'mrm'");
}

TEST_F(BagRenderTest, MeshesNamedRelativeToARecordedDescriptionAreFoundBesideTheBag) {
  // the rover's body as meshes/base_plate.stl, a path relative to the description
  fs::copy_file(test::TestBag("rover_relative_mesh.mcap"), Path("run.mcap"));
  Fails("render --bag " + Path("run.mcap"),
        "run.mcap: '/robot_description':11: link 'base_link': mesh 'meshes/base_plate.stl' not found");
  fs::create_directory(Path("meshes"));
  fs::copy_file(kSource / "models/meshbot_description/meshes/base_plate.stl", Path("meshes/base_plate.stl"));
  const std::string still = Render("--bag " + Path("run.mcap") + " --size 160x120 --distance 2");
  EXPECT_GT(RobotCentre(image::DecodePng(still, "still")).pixels, 200);
  // animate finds it there too
  Ok("animate " + Path("run.mcap") + " --size 160x120 --distance 2 --fps 2 -o " + Path("run.gif"));
}

TEST_F(BagRenderTest, BadMomentsAndFramesAreOneErrorLine) {
  const std::string bag = test::TestBag("rover_loop.mcap");
  Fails("render --bag " + bag + " --at 9", "--at 9 is outside");
  Fails("render --bag " + bag + " --at -1", "--at -1 is outside");
  Fails("render --bag " + bag + " --at soon", "--at");
  Fails("render " + kMrm + " --at 1", "--at: a moment of a recording; give the recording with --bag");
  Fails("render --size 10x10", "render: give MODEL (a URDF or xacro file) or --bag");
  Fails("render --bag " + bag + " --fixed-frame map", "--fixed-frame 'map': neither a link of the robot nor a frame");
  Fails("render --bag " + Path("missing.mcap"), "missing.mcap");
  Fails("render --bag " + test::TestBag("joint_states_zstd.mcap"),
        "joint_states_zstd.mcap: no robot description: no message on '/robot_description'");
}

}  // namespace
}  // namespace urdfsnap::cli_test
