// `urdfsnap diff`: exit statuses, the figures printed, the diff picture, and the claim behind the
// default tolerance: a re-render on another x86-64 CPU matches, a joint moved by 0.01 rad does not.
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

// mrm's "mixed" golden pose; each test moves one joint from here.
const std::string kMixedPose =
    " -j base_link__link_01=1.2 -j link_01__link_02=-0.6 -j link_02__link_03=1.1"
    " -j link_03__link_04=0.9 -j link_04__link_05=0.4";

// every test renders
class DiffTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    URDFSNAP_REQUIRE_GL();
  }

  // Renders mrm in the mixed pose (plus `extra` options) to `name` and returns its path.
  std::string Render(const std::string& name, const std::string& extra = "",
                     const std::string& environment = "") {
    const Result r = RunUrdfsnap("render " + kMrm + kMixedPose + extra + " -o " + Path(name), environment);
    EXPECT_EQ(r.status, 0) << r.output;
    return Path(name);
  }
};

TEST_F(DiffTest, IdenticalImagesMatch) {
  const std::string a = Render("a.png");
  const Result r = RunUrdfsnap("diff " + a + " " + a);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("match: max delta 0, mean delta 0.000", 0), 0u) << r.output;
}

// GALLIUM_OVERRIDE_CPU_CAPS=sse2 makes llvmpipe generate code for a CPU without AVX, the oldest
// x86-64: the nearest thing to "another machine" one machine can offer.
TEST_F(DiffTest, ReRenderOnAnotherX86CpuMatches) {
  const std::string here = Render("here.png");
  for (const char* caps : {"sse2", "sse4.1"}) {
    const std::string there = Render(std::string(caps) + ".png", "", std::string("GALLIUM_OVERRIDE_CPU_CAPS=") + caps);
    // the simulated CPU must really render differently, or this test would prove nothing
    EXPECT_NE(ReadBytes(here), ReadBytes(there)) << caps;
    const Result r = RunUrdfsnap("diff " + here + " " + there);
    EXPECT_EQ(r.status, 0) << caps << ": " << r.output;
  }
}

TEST_F(DiffTest, JointMovedByOneHundredthOfARadianDiffers) {
  const std::string before = Render("before.png");
  // link_04__link_05 turns the round tool about its own axis, which shows nothing in any viewer
  for (const char* moved : {"base_link__link_01=1.21", "link_01__link_02=-0.59",
                            "link_02__link_03=1.11", "link_03__link_04=0.91"}) {
    const std::string after = Render("after.png", std::string(" -j ") + moved);
    const Result r = RunUrdfsnap("diff " + before + " " + after);
    EXPECT_EQ(r.status, 1) << moved << ": " << r.output;
    EXPECT_EQ(r.output.rfind("differ: ", 0), 0u) << r.output;
  }
}

TEST_F(DiffTest, PrintsTheFiguresAndWritesTheDiffPicture) {
  const std::string before = Render("before.png");
  const std::string after = Render("after.png", " -j link_01__link_02=-0.5");
  const Result r = RunUrdfsnap("diff " + before + " " + after + " --diff " + Path("d.png"));
  ASSERT_EQ(r.status, 1) << r.output;
  for (const char* part : {"max delta ", "mean delta ", "pixels (", "over 8", "in x "}) {
    EXPECT_NE(r.output.find(part), std::string::npos) << part << " in " << r.output;
  }
  const image::Image diff = image::ReadPng(Path("d.png"));
  int magenta = 0, yellow = 0, grey = 0;
  for (size_t i = 0; i < diff.rgb.size(); i += 3) {
    const auto* p = &diff.rgb[i];
    magenta += p[0] == 255 && p[1] == 0 && p[2] == 255;
    yellow += p[0] == 255 && p[1] == 200 && p[2] == 0;
    grey += p[0] == p[1] && p[1] == p[2] && p[0] >= 64 && p[0] <= 127;
  }
  EXPECT_GT(magenta, 500);
  EXPECT_GT(yellow, 0);  // anti-aliased edges change a little
  EXPECT_EQ(magenta + yellow + grey, diff.width * diff.height);
  // a looser tolerance accepts the same pair
  EXPECT_EQ(RunUrdfsnap("diff " + before + " " + after + " --max-fraction 0.5 --max-mean 50").status, 0);
}

TEST_F(DiffTest, BadInputIsStatusTwoNamingTheCulprit) {
  const std::string a = Render("a.png");
  const std::string small = Render("small.png", " --size 320x200");
  const std::string text = Write("text.png", "not a png");
  struct Case {
    std::string arguments, expected_text;
  } cases[] = {
      {a + " " + Path("missing.png"), "missing.png"},
      {a + " " + text, "text.png"},
      {a + " " + small, "640x480"},
      {a + " " + small, "320x200"},
      {a + " " + a + " --max-delta 300", "--max-delta"},
  };
  for (const Case& c : cases) {
    const Result r = RunUrdfsnap("diff " + c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments << ": " << r.output;
    EXPECT_NE(r.output.find("urdfsnap: error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expected_text), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
