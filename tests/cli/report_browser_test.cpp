// The HTML report of a failing snapshot in a real browser (headless Chromium, Debian's `chromium`,
// which scripts/deps.sh installs): the three images load, depth and label pictures show in colour
// (not black), and the swipe slider moves the clip between expected and actual. Without Chromium
// the tests fail in CI (CI=true) and are skipped elsewhere.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"
#include "image/gray16_diff.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

// The first of the usual Chromium names on PATH, or "".
std::string FindChromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0) return name;
  }
  return "";
}

class ReportBrowserTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    chromium_ = FindChromium();
    if (chromium_.empty()) {
      const char* ci = std::getenv("CI");
      if (ci && std::string(ci) == "true") FAIL() << "no chromium on PATH (scripts/deps.sh installs it)";
      GTEST_SKIP() << "no chromium on PATH (scripts/deps.sh installs it; in CI this is a failure)";
    }
    URDFSNAP_REQUIRE_GL();
    // the elbow golden against the arm moved by 0.1 rad: a failing case with all three images
    fs::copy_file(kSource / "tests/golden/mrm_elbow.png", Path("elbow.png"));
    Write("suite.yaml", "cases:\n  - name: elbow\n    model: " + kMrm +
                            "\n    joints: {link_01__link_02: 0.6, link_02__link_03: -1.0}\n");
    const Result r = RunUrdfsnap("snapshot check " + Path("suite.yaml") + " --report " + Path("report"));
    ASSERT_EQ(r.status, 1) << r.output;
  }

  // Runs headless Chromium on `page` with `arguments`, returning its stdout. As root and on a
  // closed network it needs no sandbox, no GPU, nothing fetched from Google's servers (QUIC,
  // component updates, sync, first-run) and a profile of its own, else it stalls; a deadline
  // stops it should it hang anyway.
  std::string Browse(const std::string& arguments, const std::string& page) const {
    static int runs = 0;
    const std::string profile = Path("chromium-profile-" + std::to_string(++runs));
    const std::string command =
        "timeout -k 5 60 " + chromium_ +
        " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
        " --disable-component-update --disable-sync --user-data-dir=" + profile + " --hide-scrollbars " +
        arguments + " file://" + page + " 2>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    std::string output;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
    pclose(pipe);
    return output;
  }

  std::string chromium_;
};

TEST_F(ReportBrowserTest, ShowsTheThreeImages) {
  Browse("--window-size=1300,1400 --screenshot=" + Path("shot.png"), Path("report/index.html"));
  const image::Image shot = image::ReadPng(Path("shot.png"));
  // the diff image's magenta and the robot's red must be on the page, i.e. the PNGs loaded
  int magenta = 0, red = 0;
  for (size_t i = 0; i < shot.rgb.size(); i += 3) {
    const auto* p = &shot.rgb[i];
    magenta += p[0] > 200 && p[1] < 60 && p[2] > 200;
    red += p[0] > 100 && p[1] < 30 && p[2] < 30;
  }
  EXPECT_GT(magenta, 300);
  EXPECT_GT(red, 3000);
}

TEST_F(ReportBrowserTest, SliderSwipesBetweenExpectedAndActual) {
  // the report's own page, plus a script that moves the slider as a user's drag would
  std::ifstream in(Path("report/index.html"));
  std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto end = html.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  html.insert(end, "<script>const s = document.querySelector('.slider'); s.value = 20;"
                   " s.dispatchEvent(new Event('input'));</script>\n");
  Write("report/driven.html", html);
  const std::string initial = Browse("--dump-dom", Path("report/index.html"));
  EXPECT_NE(initial.find("style=\"clip-path: inset(0px 0px 0px 50%);\""), std::string::npos) << initial;
  const std::string moved = Browse("--dump-dom", Path("report/driven.html"));
  EXPECT_NE(moved.find("style=\"clip-path: inset(0px 0px 0px 20%);\""), std::string::npos) << moved;
  EXPECT_NE(moved.find("class=\"line\" style=\"left: 20%;\""), std::string::npos) << moved;
}

// Depth and label images hold millimetres and link numbers, which a browser shows black: the
// report must show its false-colour and per-link pictures instead.
TEST_F(ReportBrowserTest, ShowsDepthAndLabelPicturesNotBlack) {
  const std::string goldens = "defaults:\n  model: " + kMrm + "\ncases:\n  - name: d\n    depth: true\n"
                              "  - name: l\n    labels: true\n";
  ASSERT_EQ(RunUrdfsnap("snapshot update " + Write("goldens.yaml", goldens)).status, 0);
  std::string moved = goldens;
  for (const char* name : {"d\n", "l\n"}) {
    moved.insert(moved.find(std::string("name: ") + name) + 6 + 2, "    joints: {link_01__link_02: 0.3}\n");
  }
  Write("moved.yaml", moved);
  ASSERT_EQ(RunUrdfsnap("snapshot check " + Path("moved.yaml") + " --report " + Path("depth_report")).status, 1);
  Browse("--window-size=1300,6000 --screenshot=" + Path("depth_shot.png"), Path("depth_report/index.html"));
  const image::Image shot = image::ReadPng(Path("depth_shot.png"));
  // base_link's label colour, as LabelPicture paints label 1
  const image::Image base = image::LabelPicture(image::Gray16Image{1, 1, {1}});
  int depth_colours = 0, base_link = 0, magenta = 0;
  for (size_t i = 0; i < shot.rgb.size(); i += 3) {
    const int r = shot.rgb[i], g = shot.rgb[i + 1], b = shot.rgb[i + 2];
    // viridis's green and teal (the grid and the dimmed diff are grey, the robot red)
    depth_colours += r < 120 && g > r + 40 && b > r && g < 235;
    base_link += r == base.rgb[0] && g == base.rgb[1] && b == base.rgb[2];
    magenta += r > 200 && g < 60 && b > 200;
  }
  EXPECT_GT(depth_colours, 3000);
  EXPECT_GT(base_link, 3000);
  EXPECT_GT(magenta, 1000);
}

}  // namespace
}  // namespace urdfsnap::cli_test
