// Depth and link-label goldens in snapshot suites, against the binary: `update` writes them (the
// same files `render --depth/--labels` writes), `check` passes, reports a missing one, fails a
// joint moved by 0.01 rad with depth and label figures and viewable report pictures (also through
// shards and `merge`), and accepts a re-render for another CPU (the claim behind the defaults);
// bad values in the new keys are one located error, exit status 2. And `urdfsnap diff --depth`.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// mrm's "mixed" golden pose, as suite joints and as render options; each test moves one joint.
const std::string kMixedYaml =
    "{base_link__link_01: 1.2, link_01__link_02: -0.6, link_02__link_03: 1.1, link_03__link_04: 0.9}";
const std::string kMixedFlags =
    " -j base_link__link_01=1.2 -j link_01__link_02=-0.6 -j link_02__link_03=1.1 -j link_03__link_04=0.9";

// Pixels of `image` that are not black.
int Lit(const image::Image& image) {
  int lit = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) lit += image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2] > 0;
  return lit;
}

int CountColour(const image::Image& image, int r, int g, int b) {
  int count = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) {
    count += image.rgb[i] == r && image.rgb[i + 1] == g && image.rgb[i + 2] == b;
  }
  return count;
}

class SnapshotDepthTest : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    URDFSNAP_REQUIRE_GL();
  }

  // A suite of mrm cases (each "  - name: ...\n..." text) with depth and labels goldens.
  std::string Suite(const std::string& cases, const std::string& name = "suite.yaml") const {
    return Write(name, "defaults:\n  model: " + kMrm + "\n  depth: true\n  labels: true\ncases:\n" + cases);
  }
};

TEST_F(SnapshotDepthTest, UpdateWritesWhatRenderWritesAndCheckPasses) {
  const std::string suite = Suite("  - name: home\n    golden: goldens/home.png\n    joints: " + kMixedYaml + "\n");
  Result r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "MISSING  home: no golden image")) << r.output;
  EXPECT_TRUE(Contains(r.output, "depth: no depth golden " + Path("goldens/home.depth.png"))) << r.output;

  r = RunUrdfsnap("snapshot update " + suite);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, "wrote    home: " + Path("goldens/home.png") + ", " + Path("goldens/home.camera.json") + ", " +
                                     Path("goldens/home.depth.png") +
                                     ", " + Path("goldens/home.labels.png") + " (was MISSING)")) << r.output;
  // the goldens are render's files, byte for byte, with the link names beside the labels
  ASSERT_EQ(RunUrdfsnap("render " + kMrm + kMixedFlags + " -o " + Path("r.png") + " --depth " + Path("r.depth.png") +
                        " --labels " + Path("r.labels.png")).status, 0);
  for (const char* kind : {".png", ".depth.png", ".labels.png", ".labels.json"}) {
    EXPECT_EQ(ReadBytes(Path(std::string("goldens/home") + kind)), ReadBytes(Path(std::string("r") + kind))) << kind;
  }
  EXPECT_TRUE(Contains(ReadBytes(Path("goldens/home.labels.json")), "\"1\": \"base_link\""));

  r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, "; depth: max delta 0 mm, 0 pixels (0.000%) over 2 mm (limit 0.01%)")) << r.output;
  EXPECT_TRUE(Contains(r.output, "; labels: 0 pixels (0.000%) differ (limit 0%)")) << r.output;

  // a missing depth golden alone: MISSING, and update writes that one only
  fs::remove(Path("goldens/home.depth.png"));
  r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "MISSING  home: max delta 0")) << r.output;
  EXPECT_TRUE(Contains(r.output, "depth: no depth golden")) << r.output;
  r = RunUrdfsnap("snapshot update " + suite);
  EXPECT_TRUE(Contains(r.output, "wrote    home: " + Path("goldens/home.depth.png") + " (was MISSING)")) << r.output;
  EXPECT_TRUE(Contains(r.output, "1 golden files of 1 cases written")) << r.output;
  EXPECT_TRUE(Contains(RunUrdfsnap("snapshot update " + suite).output, "same     home")) << r.output;
}

// Colour's tolerance opened wide: depth and labels alone must catch a joint moved by 0.01 rad.
// (link_04__link_05 turns the round tool about its own axis, which shows in no image.)
TEST_F(SnapshotDepthTest, JointMovedByOneHundredthOfARadianFailsWithDepthAndLabelFigures) {
  const std::string loose = "    max-fraction: 1\n    max-mean: 255\n";
  ASSERT_EQ(RunUrdfsnap("snapshot update " + Suite("  - name: mixed\n    joints: " + kMixedYaml + "\n")).status, 0);
  for (const auto& [joint, value] : {std::pair{"base_link__link_01", "1.2"}, std::pair{"link_01__link_02", "-0.6"},
                                     std::pair{"link_02__link_03", "1.1"}, std::pair{"link_03__link_04", "0.9"}}) {
    std::string joints = kMixedYaml;
    const std::string old = std::string(joint) + ": " + value;
    joints.replace(joints.find(old), old.size(), std::string(joint) + ": " + std::to_string(std::stod(value) + 0.01));
    const Result r = RunUrdfsnap("snapshot check " +
                                 Suite("  - name: moved\n    golden: mixed.png\n    depth-golden: mixed.depth.png\n"
                                       "    labels-golden: mixed.labels.png\n    joints: " + joints + "\n" + loose,
                                       "moved.yaml"));
    EXPECT_EQ(r.status, 1) << joints << ": " << r.output;
    EXPECT_TRUE(Contains(r.output, "FAILED   moved: ")) << r.output;
    EXPECT_TRUE(Contains(r.output, "; depth: max delta ")) << r.output;
    EXPECT_TRUE(Contains(r.output, " over 2 mm (limit 0.01%), ")) << r.output;  // with the pixels' region
    EXPECT_TRUE(Contains(r.output, " differ (limit 0%), ")) << r.output;
    EXPECT_TRUE(Contains(r.output, "links ")) << r.output;
  }
}

TEST_F(SnapshotDepthTest, FailingCaseReportsDepthAndLabelPicturesThroughShardsAndMerge) {
  const std::string before = Suite("  - name: a\n  - name: b\n    yaw: 1.5\n  - name: c\n    fit: true\n");
  ASSERT_EQ(RunUrdfsnap("snapshot update " + before).status, 0);
  // every case's arm raised by 0.2 rad
  const std::string after = Suite("  - name: a\n    joints: {link_01__link_02: 0.2}\n  - name: b\n    yaw: 1.5\n"
                                  "    joints: {link_01__link_02: 0.2}\n  - name: c\n    fit: true\n"
                                  "    joints: {link_01__link_02: 0.2}\n");
  const Result whole = RunUrdfsnap("snapshot check " + after + " --report " + Path("report") + " --results " +
                                   Path("results.json") + " --junit " + Path("junit.xml"));
  ASSERT_EQ(whole.status, 1) << whole.output;
  for (const char* kind : {"depth", "labels"}) {
    for (const char* image : {"expected", "actual", "diff"}) {
      const std::string file = std::string("a.") + kind + "." + image + ".png";
      const image::Image picture = image::ReadPng(Path("report/" + file));
      EXPECT_GT(Lit(picture), 5000) << file << ": black";  // the robot is visible, not black
      EXPECT_TRUE(Contains(ReadBytes(Path("report/index.html")), "src=\"" + file + "\"")) << file;
    }
    const image::Image diff = image::ReadPng(Path(std::string("report/a.") + kind + ".diff.png"));
    EXPECT_GT(CountColour(diff, 255, 0, 255) + CountColour(diff, 0, 255, 255), 500) << kind;
  }
  std::ifstream in(Path("results.json"));
  const auto results = nlohmann::json::parse(in);
  const auto& a = results["cases"][0];
  EXPECT_EQ(a["depth"]["status"], "failed");
  EXPECT_GT(a["depth"]["figures"]["max_delta"].get<int>(), 50);
  EXPECT_GT(a["depth"]["figures"]["pixels_coverage"].get<int>(), 0);
  EXPECT_EQ(a["depth"]["tolerance"]["max_delta"], 2);
  EXPECT_EQ(a["labels"]["images"]["diff"], "a.labels.diff.png");
  EXPECT_TRUE(Contains(ReadBytes(Path("junit.xml")), "depth golden: " + Path("a.depth.png") + " (FAILED)"));

  // shards, then merged: the same verdicts and every picture in the merged report
  for (const char* k : {"1", "2"}) {
    RunUrdfsnap("snapshot check " + after + " --shard " + k + "/2 --report " + Path(std::string("s") + k + "/report") +
                " --results " + Path(std::string("s") + k + "/results.json"));
  }
  const Result merged = RunUrdfsnap("snapshot merge " + Path("s1/results.json") + " " + Path("s2/results.json") +
                                    " --report " + Path("merged") + " --results " + Path("merged.json"));
  EXPECT_EQ(merged.status, 1) << merged.output;
  for (const auto& entry : fs::directory_iterator(Path("report"))) {
    const std::string name = entry.path().filename().string();
    if (name == "index.html") continue;
    EXPECT_EQ(ReadBytes(Path("merged/" + name)), ReadBytes(entry.path().string())) << name;
  }
  std::ifstream merged_in(Path("merged.json"));
  const auto merged_results = nlohmann::json::parse(merged_in);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(merged_results["cases"][i]["depth"]["figures"], results["cases"][i]["depth"]["figures"]) << i;
  }
}

// GALLIUM_OVERRIDE_CPU_CAPS=sse2 makes llvmpipe generate code for a CPU without AVX: its depth
// differs by a millimetre here and there (so the test proves something), within the defaults.
TEST_F(SnapshotDepthTest, ReRenderOnAnotherX86CpuMatches) {
  const std::string suite = Suite("  - name: mixed\n    joints: " + kMixedYaml + "\n  - name: close\n"
                                  "    joints: " + kMixedYaml + "\n    yaw: 2\n    pitch: 0.5\n    distance: 2\n"
                                  "    focal: [0, 0, 0.5]\n");
  ASSERT_EQ(RunUrdfsnap("snapshot update " + suite).status, 0);
  const Result r = RunUrdfsnap("snapshot check " + suite, "GALLIUM_OVERRIDE_CPU_CAPS=sse2");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, "depth: max delta 1 mm, 0 pixels")) << r.output;
  ASSERT_EQ(RunUrdfsnap("render " + kMrm + kMixedFlags + " -o " + Path("o.png") + " --depth " + Path("sse2.png"),
                        "GALLIUM_OVERRIDE_CPU_CAPS=sse2").status, 0);
  EXPECT_NE(ReadBytes(Path("sse2.png")), ReadBytes(Path("mixed.depth.png")));
}

TEST_F(SnapshotDepthTest, BadValuesInTheNewKeysAreOneLocatedError) {
  struct Case {
    std::string yaml, expected;
  } cases[] = {
      {"    depth: maybe\n", "suite.yaml:5: 'depth': expected true or false, got 'maybe'"},
      {"    labels: [1, 2]\n", "suite.yaml:5: 'labels': expected true or false"},
      {"    depth-max-delta: -1\n", "suite.yaml:5: 'depth-max-delta': expected a number from 0 to 65535, got '-1'"},
      {"    depth-max-delta: 1e99\n", "suite.yaml:5: 'depth-max-delta': expected a number from 0 to 65535"},
      {"    depth-max-fraction: nan\n", "suite.yaml:5: 'depth-max-fraction': expected a number from 0 to 1, got 'nan'"},
      {"    labels-max-fraction: 2\n", "suite.yaml:5: 'labels-max-fraction': expected a number from 0 to 1"},
      {"    labels-max-delta: 1\n", "suite.yaml:5: unknown key 'labels-max-delta'"},
      {"    depth-golden: {a: 1}\n", "suite.yaml:5: 'depth-golden': expected a value"},
      {"    depth: false\n    depth-golden: d.png\n", "suite.yaml:6: 'depth-golden' given with 'depth: false'"},
      {"    depth-golden: a.png\n    depth-golden: b.png\n", "suite.yaml:6: 'depth-golden' is given twice"},
  };
  for (const Case& c : cases) {
    const Result r = RunUrdfsnap("snapshot check " + Write("suite.yaml", "defaults:\n  model: " + kMrm +
                                                                            "\ncases:\n  - name: a\n" + c.yaml));
    EXPECT_EQ(r.status, 2) << c.yaml << r.output;
    // one line
    EXPECT_EQ(r.output.rfind("urdfsnap: error: " + Path(c.expected), 0), 0u) << c.yaml << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  const Result in_defaults = RunUrdfsnap("snapshot check " + Write("suite.yaml", "defaults:\n  labels-golden: l.png\n"
                                                                                 "cases:\n  - name: a\n"));
  EXPECT_EQ(in_defaults.status, 2);
  EXPECT_TRUE(Contains(in_defaults.output, "suite.yaml:2: 'labels-golden' belongs to a case, not to 'defaults'"))
      << in_defaults.output;
}

// A golden that is not a PNG is an error (status 2) naming it; one of another size fails.
TEST_F(SnapshotDepthTest, BrokenOrResizedDepthGoldens) {
  const std::string suite = Suite("  - name: a\n    depth-golden: d/a.png\n");
  ASSERT_EQ(RunUrdfsnap("snapshot update " + suite).status, 0);
  ASSERT_TRUE(fs::exists(Path("d/a.png")));
  ASSERT_EQ(RunUrdfsnap("render " + kMrm + " --size 320x240 -o " + Path("small.png") + " --depth " + Path("d/a.png")).status, 0);
  Result r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "depth: size differs: depth golden " + Path("d/a.png") + " is 320x240, the render is 640x480"))
      << r.output;
  Write("d/a.png", "not a png");
  r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(Contains(r.output, "ERROR    a: ")) << r.output;
  EXPECT_TRUE(Contains(r.output, Path("d/a.png"))) << r.output;
}

TEST_F(SnapshotDepthTest, DiffComparesDepthInMillimetresAndLabels) {
  const auto render = [&](const std::string& name, const std::string& joints) {
    ASSERT_EQ(RunUrdfsnap("render " + kMrm + kMixedFlags + joints + " -o " + Path(name + ".png") + " --depth " +
                          Path(name + ".d.png") + " --labels " + Path(name + ".l.png")).status, 0);
  };
  render("a", "");
  render("b", " -j link_01__link_02=-0.59");
  Result r = RunUrdfsnap("diff --depth " + Path("a.d.png") + " " + Path("a.d.png"));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "match: max delta 0 mm, 0 pixels (0.000%) over 2 mm (limit 0.01%)\n");
  r = RunUrdfsnap("diff --depth " + Path("a.d.png") + " " + Path("b.d.png") + " --diff " + Path("d.png"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "differ: max delta ")) << r.output;
  EXPECT_TRUE(Contains(r.output, "robot in one image only")) << r.output;
  const image::Image diff = image::ReadPng(Path("d.png"));
  EXPECT_GT(CountColour(diff, 255, 0, 255), 300);
  EXPECT_GT(CountColour(diff, 0, 255, 255), 10);
  EXPECT_EQ(RunUrdfsnap("diff --depth --max-delta 1000 --max-fraction 0.01 " + Path("a.d.png") + " " + Path("b.d.png")).status, 0);
  r = RunUrdfsnap("diff --labels " + Path("a.l.png") + " " + Path("b.l.png"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "differ (limit 0%)")) << r.output;
  // colour, depth and labels options that do not go together
  for (const std::string bad : {"--labels --max-delta 1", "--depth --max-mean 1", "--depth --labels",
                                 "--max-delta 256", "--depth --max-delta 70000"}) {
    r = RunUrdfsnap("diff " + bad + " " + Path("a.d.png") + " " + Path("b.d.png"));
    EXPECT_EQ(r.status, 2) << bad << ": " << r.output;
    EXPECT_TRUE(Contains(r.output, "urdfsnap: error: ")) << bad << ": " << r.output;
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
