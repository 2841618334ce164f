// `urdfsnap animate a.mcap b.mcap ... -o out/{stem}...`: every bag animated with the same options
// into its own outputs, each as animating it alone makes them; a bad bag among them gets its error
// line while the others are still written, then exit status 2; outputs without {stem} or two bags
// of one name are refused before anything is written.
#include <filesystem>

#include <gtest/gtest.h>

#include "bag/test_bags.h"
#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

const std::string kOptions = " --fps 2 --end 1 --size 80x60 --yaw 0.8 --pitch 0.5 --distance 2.5";

class ManyBagsTest : public CliTest {
 protected:
  void SetUp() override {
    URDFSNAP_REQUIRE_GL();
    CliTest::SetUp();
    // two names for the rover's recording (tests/node/make_test_bags.mjs)
    fs::copy_file(test::TestBag("rover_loop.mcap"), Path("east.mcap"));
    fs::copy_file(test::TestBag("rover_loop.mcap"), Path("west.mcap"));
  }
};

TEST_F(ManyBagsTest, EachBagIsAnimatedAsAloneAndABadOneDoesNotStopTheOthers) {
  const std::string junk = test::TestBag("description_junk.mcap");
  const Result many = RunUrdfsnap("animate " + Path("east.mcap") + " " + junk + " " + Path("west.mcap") + kOptions +
                                  " -o " + Path("out/{stem}/%d.png"));
  EXPECT_EQ(many.status, 2) << many.output;
  EXPECT_NE(many.output.find("urdfsnap: error: " + junk + ": '/robot_description'"), std::string::npos) << many.output;
  EXPECT_NE(many.output.find("urdfsnap: animated 2 of 3 bags; failed: " + junk), std::string::npos) << many.output;
  EXPECT_FALSE(fs::exists(Path("out/description_junk")));
  const Result alone = RunUrdfsnap("animate " + Path("east.mcap") + kOptions + " -o " + Path("alone/%d.png"));
  ASSERT_EQ(alone.status, 0) << alone.output;
  for (const std::string frame : {"0.png", "1.png", "2.png"}) {
    EXPECT_EQ(ReadBytes(Path("out/east/" + frame)), ReadBytes(Path("alone/" + frame))) << frame;
    EXPECT_EQ(ReadBytes(Path("out/west/" + frame)), ReadBytes(Path("alone/" + frame))) << frame;
  }
  const Result good = RunUrdfsnap("animate " + Path("east.mcap") + " " + Path("west.mcap") + kOptions + " -o " +
                                  Path("gifs/{stem}.gif"));
  EXPECT_EQ(good.status, 0) << good.output;
  EXPECT_NE(good.output.find("urdfsnap: animated 2 of 2 bags"), std::string::npos) << good.output;
  EXPECT_TRUE(fs::exists(Path("gifs/east.gif")) && fs::exists(Path("gifs/west.gif")));
}

TEST_F(ManyBagsTest, OutputsThatWouldOverwriteEachOtherAreRefused) {
  const Result plain = RunUrdfsnap("animate " + Path("east.mcap") + " " + Path("west.mcap") + kOptions + " -o " +
                                   Path("one.gif"));
  EXPECT_EQ(plain.status, 2);
  EXPECT_NE(plain.output.find("put {stem} (each bag's name) in it"), std::string::npos) << plain.output;
  fs::create_directory(Path("again"));
  fs::copy_file(Path("east.mcap"), Path("again/east.mcap"));
  const Result same = RunUrdfsnap("animate " + Path("east.mcap") + " " + Path("again/east.mcap") + kOptions +
                                  " -o " + Path("{stem}.gif"));
  EXPECT_EQ(same.status, 2);
  EXPECT_NE(same.output.find("have the same name 'east'"), std::string::npos) << same.output;
  EXPECT_FALSE(fs::exists(Path("one.gif")) || fs::exists(Path("east.gif")));
}

}  // namespace
}  // namespace urdfsnap::cli_test
