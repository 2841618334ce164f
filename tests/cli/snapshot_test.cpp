// `urdfsnap snapshot check|update`: goldens created and accepted, a 0.01 rad change caught with a
// report, suite errors located, and the suite rendering exactly what `render` renders, byte for
// byte, whatever LP_NUM_THREADS is.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

using SnapshotTest = CliTest;

TEST_F(SnapshotTest, MissingGoldenFailsCheckAndUpdateCreatesIt) {
  URDFSNAP_REQUIRE_GL();
  const std::string suite = Write("suite.yaml", "cases:\n  - name: home\n    model: " + kMrm +
                                                    "\n    golden: goldens/home.png\n");
  Result r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "MISSING  home")) << r.output;

  r = RunUrdfsnap("snapshot update " + suite);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, "wrote    home")) << r.output;
  const std::string golden = ReadBytes(Path("goldens/home.png"));
  ASSERT_FALSE(golden.empty());

  r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, "1 cases: 1 passed")) << r.output;

  // a golden that still matches is left alone unless --force
  r = RunUrdfsnap("snapshot update " + suite + " home");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(Contains(r.output, "same     home")) << r.output;
  EXPECT_TRUE(Contains(RunUrdfsnap("snapshot update --force " + suite).output, "wrote    home"));
  EXPECT_EQ(ReadBytes(Path("goldens/home.png")), golden);
}

// The machinery's reason to exist: mrm_elbow's golden against the arm moved by 0.01 rad.
TEST_F(SnapshotTest, JointMovedByOneHundredthOfARadianFailsWithAReport) {
  URDFSNAP_REQUIRE_GL();
  fs::copy_file(kSource / "tests/golden/mrm_elbow.png", Path("elbow.png"));
  const std::string suite =
      Write("suite.yaml", "defaults:\n  model: " + kMrm +
                              "\ncases:\n  - name: elbow\n"
                              "    joints: {link_01__link_02: 0.51, link_02__link_03: -1.0}\n");
  const Result r = RunUrdfsnap("snapshot check " + suite + " --report " + Path("report") +
                               " --junit " + Path("junit.xml"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(Contains(r.output, "FAILED   elbow: max delta")) << r.output;
  EXPECT_TRUE(Contains(r.output, "snapshot update")) << r.output;
  for (const char* file : {"elbow.expected.png", "elbow.actual.png", "elbow.diff.png"}) {
    EXPECT_TRUE(fs::exists(Path("report/") + file)) << file;
  }
  const std::string html = ReadBytes(Path("report/index.html"));
  for (const char* part : {"src=\"elbow.expected.png\"", "src=\"elbow.actual.png\"",
                           "src=\"elbow.diff.png\"", "type=\"range\"", "clipPath"}) {
    EXPECT_TRUE(Contains(html, part)) << part;
  }
  const std::string junit = ReadBytes(Path("junit.xml"));
  EXPECT_TRUE(Contains(junit, "<testcase classname=\"urdfsnap.suite\" name=\"elbow\"")) << junit;
  EXPECT_TRUE(Contains(junit, "<failure type=\"FAILED\" message=\"max delta")) << junit;
}

TEST_F(SnapshotTest, SuiteErrorsNameTheFileAndLine) {
  struct Case {
    std::string yaml, expected;
  } cases[] = {
      {"cases:\n  - name: a\n    model: m.urdf\n    yaww: 1\n", "suite.yaml:4: unknown key 'yaww' (did you mean 'yaw'? known: name, "},
      {"cases:\n  - name: a\n    model: m.urdf\n    fit: maybe\n", "suite.yaml:4: 'fit': expected true or false"},
      {"cases:\n  - name: a\n", "suite.yaml:2: case 'a' has no 'model'"},
      {"cases:\n  - name: a b\n    model: m.urdf\n", "suite.yaml:2: case name 'a b'"},
      {"cases:\n  - {name: a, model: m.urdf}\n  - {name: a, model: m.urdf}\n",
       "suite.yaml:3: a second case named 'a'"},
      {"defaults:\n  name: x\ncases: []\n", "suite.yaml:2: 'name' belongs to a case"},
      {"cases: [\n", "suite.yaml:2: bad YAML"},
      {"case:\n  - name: a\n", "suite.yaml:1: unknown key 'case' (did you mean 'cases'? expected"},
      {"cases:\n  - name: a\n    model: " + kMrm + "\n    joints: {link_01__link_02: x}\n",
       "suite.yaml:4: 'joints: link_01__link_02': expected a number"},
  };
  for (const Case& c : cases) {
    const Result r = RunUrdfsnap("snapshot check " + Write("suite.yaml", c.yaml));
    EXPECT_EQ(r.status, 2) << c.yaml << r.output;
    EXPECT_TRUE(Contains(r.output, "urdfsnap: error: ")) << r.output;
    EXPECT_TRUE(Contains(r.output, c.expected)) << c.expected << " in " << r.output;
  }
  EXPECT_TRUE(Contains(RunUrdfsnap("snapshot check " + Path("none.yaml")).output, "none.yaml"));
}

// A case that cannot be rendered is reported at its line; the other cases still run.
TEST_F(SnapshotTest, CaseErrorsAreStatusTwoAfterTheOtherCases) {
  URDFSNAP_REQUIRE_GL();
  const std::string suite = Write(
      "suite.yaml", "defaults:\n  model: " + kMrm +
                        "\ncases:\n  - name: bad_value\n    yaw: abc\n  - name: bad_joint\n"
                        "    joints: {elbow: 1}\n  - name: fine\n");
  const Result r = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(Contains(r.output, "ERROR    bad_value: " + Path("suite.yaml") + ":5: yaw 'abc'")) << r.output;
  EXPECT_TRUE(Contains(r.output, "suite.yaml:6: case 'bad_joint': ")) << r.output;
  EXPECT_TRUE(Contains(r.output, "'elbow'")) << r.output;
  EXPECT_TRUE(Contains(r.output, "MISSING  fine")) << r.output;
}

// One process for the whole suite must render each case exactly as `render` does alone, and
// llvmpipe's thread count must not change a byte.
TEST_F(SnapshotTest, SuiteOutputIsByteIdenticalToRenderAndAcrossThreadCounts) {
  URDFSNAP_REQUIRE_GL();
  const std::string xacro = (kSource / "models/mrm_description/urdf/mrm.xacro").string();
  const std::string rviz = (kSource / "tests/data/mrm.rviz").string();
  struct View {
    std::string name, yaml, flags;
  } views[] = {
      {"plain", "", ""},
      {"posed_fit", "    joints: {link_01__link_02: 0.5}\n    fit: true\n", "-j link_01__link_02=0.5 --fit"},
      {"tf_collision", "    tf: true\n    collision: true\n    alpha: 0.5\n    size: 320x240\n",
       "--tf --collision --alpha 0.5 --size 320x240"},
      {"xacro_view", "    model: " + xacro + "\n    yaw: 1.2\n    background: [255, 255, 255]\n    no-grid: true\n",
       "--yaw 1.2 --background 255,255,255 --no-grid"},
      {"from_rviz", "    rviz: " + rviz + "\n    no-aa: true\n", "--rviz " + rviz + " --no-aa"},
  };
  // the defaults' joints apply to every case, a case's joints add to them
  std::string yaml = "defaults:\n  model: " + kMrm + "\n  joints: {link_02__link_03: 0.3}\ncases:\n";
  for (const View& v : views) yaml += "  - name: " + v.name + "\n    golden: " + v.name + ".png\n" + v.yaml;
  fs::create_directories(Path("t1"));
  fs::create_directories(Path("t8"));
  Write("t1/suite.yaml", yaml);
  Write("t8/suite.yaml", yaml);
  ASSERT_EQ(RunUrdfsnap("snapshot update " + Path("t1/suite.yaml"), "LP_NUM_THREADS=1").status, 0);
  ASSERT_EQ(RunUrdfsnap("snapshot update " + Path("t8/suite.yaml"), "LP_NUM_THREADS=8").status, 0);
  for (const View& v : views) {
    const std::string model = Contains(v.yaml, "model:") ? xacro : kMrm;
    const std::string flags = "-j link_02__link_03=0.3 " + v.flags;
    const Result r = RunUrdfsnap("render " + model + " " + flags + " -o " + Path(v.name + ".png"),
                                 "LP_NUM_THREADS=2");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string alone = ReadBytes(Path(v.name + ".png"));
    EXPECT_EQ(ReadBytes(Path("t1/" + v.name + ".png")), alone) << v.name;
    EXPECT_EQ(ReadBytes(Path("t8/" + v.name + ".png")), alone) << v.name;
    // and run after run
    ASSERT_EQ(RunUrdfsnap("render " + model + " " + flags + " -o " + Path("again.png")).status, 0);
    EXPECT_EQ(ReadBytes(Path("again.png")), alone) << v.name;
  }
}

}  // namespace
}  // namespace urdfsnap::cli_test
