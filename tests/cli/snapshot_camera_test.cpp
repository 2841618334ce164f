// Snapshot goldens store the camera they were drawn with (NAME.camera.json): with `fit: true`,
// shortening one link by 5 cm fails the case on that link's pixels only (drawn with the stored
// camera), "camera moved" is reported apart (stdout, results file, HTML report), `update` stores
// the new camera, and a golden without a camera file (from before) is checked as before.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace urdfsnap::cli_test {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A post with an arm along +X whose last link is `tip` m long.
std::string Arm(double tip) {
  const std::string length = std::to_string(tip);
  return "<robot name=\"arm\">"
         "<link name=\"post\"><visual><origin xyz=\"0 0 0.3\"/><geometry><box size=\"0.1 0.1 0.6\"/></geometry>"
         "</visual></link>"
         "<link name=\"upper\"><visual><origin xyz=\"0.25 0 0\"/><geometry><box size=\"0.5 0.08 0.08\"/></geometry>"
         "</visual></link>"
         "<link name=\"tip\"><visual><origin xyz=\"" + std::to_string(tip / 2) + " 0 0\"/><geometry><box size=\"" +
         length + " 0.05 0.05\"/></geometry></visual></link>"
         "<joint name=\"shoulder\" type=\"fixed\"><parent link=\"post\"/><child link=\"upper\"/>"
         "<origin xyz=\"0 0 0.6\"/></joint>"
         "<joint name=\"elbow\" type=\"fixed\"><parent link=\"upper\"/><child link=\"tip\"/>"
         "<origin xyz=\"0.5 0 0\"/></joint></robot>";
}

// The colour comparison's fraction of pixels over the tolerance in a results file.
double FractionOver(const std::string& results) {
  const nlohmann::json file = nlohmann::json::parse(ReadBytes(results));
  return file["cases"][0]["figures"]["fraction_over"].get<double>();
}

using SnapshotCameraTest = CliTest;

TEST_F(SnapshotCameraTest, AFittedCaseFailsOnlyWhereTheModelChangedAndReportsTheCameraApart) {
  URDFSNAP_REQUIRE_GL();
  Write("arm.urdf", Arm(0.4));
  const std::string suite =
      Write("suite.yaml", "cases:\n  - name: arm\n    model: arm.urdf\n    fit: true\n    size: 160x120\n");
  ASSERT_EQ(RunUrdfsnap("snapshot update " + suite).status, 0);
  const std::string camera = ReadBytes(Path("arm.camera.json"));
  ASSERT_TRUE(Contains(camera, "\"format\": \"urdfsnap-golden-camera\"")) << camera;
  EXPECT_EQ(RunUrdfsnap("snapshot check " + suite).status, 0);

  Write("arm.urdf", Arm(0.35));   // the last link 5 cm shorter: the fit now frames it closer
  const Result stored = RunUrdfsnap("snapshot check " + suite + " --results " + Path("stored.json") +
                                    " --report " + Path("report"));
  EXPECT_EQ(stored.status, 1) << stored.output;
  EXPECT_TRUE(Contains(stored.output, "FAILED   arm: camera moved: the eye by ")) << stored.output;
  EXPECT_TRUE(Contains(ReadBytes(Path("report/index.html")), "camera moved")) << stored.output;
  const nlohmann::json results = nlohmann::json::parse(ReadBytes(Path("stored.json")));
  EXPECT_TRUE(Contains(results["cases"][0]["camera"].get<std::string>(), "camera moved"));

  // without the stored camera the fit moves every pixel of the robot: the stored camera confines
  // the difference to the shortened link
  fs::rename(Path("arm.camera.json"), Path("kept.json"));
  const Result moved = RunUrdfsnap("snapshot check " + suite + " --results " + Path("moved.json"));
  EXPECT_EQ(moved.status, 1) << moved.output;
  EXPECT_FALSE(Contains(moved.output, "camera moved")) << moved.output;
  const double confined = FractionOver(Path("stored.json")), whole = FractionOver(Path("moved.json"));
  EXPECT_GT(confined, 0);
  EXPECT_LT(confined, whole / 3) << "stored camera " << confined << ", refitted " << whole;
  fs::rename(Path("kept.json"), Path("arm.camera.json"));

  // update accepts the change and stores the new camera; check passes again
  const Result update = RunUrdfsnap("snapshot update " + suite);
  EXPECT_EQ(update.status, 0) << update.output;
  EXPECT_NE(ReadBytes(Path("arm.camera.json")), camera);
  EXPECT_EQ(RunUrdfsnap("snapshot check " + suite).status, 0);
}

TEST_F(SnapshotCameraTest, AGoldenWithoutACameraIsCheckedAsBeforeAndUpdateAddsTheCamera) {
  URDFSNAP_REQUIRE_GL();
  Write("arm.urdf", Arm(0.4));
  const std::string suite =
      Write("suite.yaml", "cases:\n  - name: arm\n    model: arm.urdf\n    fit: true\n    size: 80x60\n");
  ASSERT_EQ(RunUrdfsnap("snapshot update " + suite).status, 0);
  fs::remove(Path("arm.camera.json"));
  const std::string golden = ReadBytes(Path("arm.png"));
  EXPECT_EQ(RunUrdfsnap("snapshot check " + suite).status, 0);
  // the golden still matches: update writes the camera file only
  const Result update = RunUrdfsnap("snapshot update " + suite);
  EXPECT_EQ(update.status, 0) << update.output;
  EXPECT_TRUE(Contains(update.output, "arm.camera.json")) << update.output;
  EXPECT_TRUE(fs::exists(Path("arm.camera.json")));
  EXPECT_EQ(ReadBytes(Path("arm.png")), golden);
  // a camera file that is not one is a located error
  Write("arm.camera.json", "{\"format\": \"something else\"}");
  const Result bad = RunUrdfsnap("snapshot check " + suite);
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_TRUE(Contains(bad.output, "arm.camera.json: not a golden camera file")) << bad.output;
}

}  // namespace
}  // namespace urdfsnap::cli_test
