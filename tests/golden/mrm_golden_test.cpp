// Golden images of the mrm robot at three poses (default RViz view, 640x480, 4x MSAA).
//
// Tolerance: llvmpipe rasterises deterministically, so on the machine that made a golden the
// re-render is identical; another CPU or Mesa build may round a few edge samples differently. A
// pixel counts as changed when a channel differs by more than kDelta; a test fails when more than
// kMaxChangedFraction of the pixels changed or the mean channel difference exceeds kMaxMean. A
// joint moved by 0.01 rad shifts the arm's edges by 1-3 pixels over several hundred pixels, which
// exceeds these limits (see the "Sensitivity" test).
//
// On failure the expected, actual and diff images are written to <build dir>/golden-failures/.
// Regenerate after an intended change: scripts/update-goldens.sh (sets URDFSNAP_UPDATE_GOLDEN=1).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "image/image_diff.h"
#include "image/png_reader.h"
#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"
#include "render/renderer.h"
#include "render/scene_builder.h"

namespace urdfsnap {
namespace {

constexpr int kDelta = 24;
constexpr double kMaxChangedFraction = 0.0005;
constexpr double kMaxMean = 0.25;

const std::filesystem::path kSource = URDFSNAP_SOURCE_DIR;

std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Pose {
  const char* name;
  model::NamedValues joints;
};

// Names the pose in test listings instead of dumping its bytes.
void PrintTo(const Pose& pose, std::ostream* out) { *out << pose.name; }

class MrmGolden : public ::testing::TestWithParam<Pose> {
 protected:
  static void SetUpTestSuite() { renderer_ = new render::Renderer(4); }
  static void TearDownTestSuite() { delete renderer_; }

  static image::Image Render(const model::NamedValues& joints) {
    Warnings warnings;
    const model::Robot robot = model::LoadRobot(
        ReadText(kSource / "models/mrm_description/urdf/mrm.urdf"), "mrm.urdf", warnings);
    const auto positions = model::ResolveJointPositions(robot, joints, true, warnings);
    const render::Scene scene =
        render::BuildScene(robot, model::ComputeLinkPoses(robot, positions), {}, warnings);
    EXPECT_TRUE(warnings.empty());
    return renderer_->Render(scene, render::OrbitView{}, 640, 480);
  }

  static render::Renderer* renderer_;
};
render::Renderer* MrmGolden::renderer_ = nullptr;

// Checks `actual` against tests/golden/<name>.png, writing the images on failure.
void ExpectMatchesGolden(const image::Image& actual, const std::string& name) {
  const std::filesystem::path golden = kSource / "tests/golden" / (name + ".png");
  if (std::getenv("URDFSNAP_UPDATE_GOLDEN")) {
    image::WritePng(actual, golden.string());
    GTEST_SKIP() << "golden image rewritten: " << golden;
  }
  const image::Image expected = image::ReadPng(golden.string());
  const image::DiffStats stats = image::CompareImages(expected, actual, kDelta);
  const double fraction = stats.fraction_over;
  if (fraction > kMaxChangedFraction || stats.mean_delta > kMaxMean) {
    const std::filesystem::path dir = std::filesystem::path(URDFSNAP_BINARY_DIR) / "golden-failures";
    std::filesystem::create_directories(dir);
    image::WritePng(expected, (dir / (name + ".expected.png")).string());
    image::WritePng(actual, (dir / (name + ".actual.png")).string());
    image::WritePng(image::MakeDiffImage(expected, actual, kDelta), (dir / (name + ".diff.png")).string());
    ADD_FAILURE() << name << ": " << stats.pixels_over << " pixels differ by more than " << kDelta
                  << " (fraction " << fraction << ", max " << stats.max_delta << ", mean "
                  << stats.mean_delta << "); images in " << dir;
  }
}

TEST_P(MrmGolden, MatchesGoldenImage) {
  const image::Image actual = Render(GetParam().joints);
  // a black or empty frame must never pass: the robot's red must be there
  int red = 0;
  for (size_t i = 0; i < actual.rgb.size(); i += 3) red += actual.rgb[i] > 100 && actual.rgb[i + 1] < 30;
  EXPECT_GT(red, 5000);
  ExpectMatchesGolden(actual, std::string("mrm_") + GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(
    Poses, MrmGolden,
    ::testing::Values(Pose{"zero", {}},
                      Pose{"elbow", {{"link_01__link_02", 0.5}, {"link_02__link_03", -1.0}}},
                      Pose{"mixed", {{"base_link__link_01", 1.2}, {"link_01__link_02", -0.6},
                                     {"link_02__link_03", 1.1}, {"link_03__link_04", 0.9},
                                     {"link_04__link_05", 0.4}}}),
    [](const auto& info) { return std::string(info.param.name); });

// The tolerance must catch a joint moved by 0.01 rad.
TEST_F(MrmGolden, SensitivityToASmallJointChange) {
  const image::Image a = Render({{"link_01__link_02", 0.5}});
  const image::Image b = Render({{"link_01__link_02", 0.51}});
  const image::DiffStats stats = image::CompareImages(a, b, kDelta);
  EXPECT_GT(stats.fraction_over, kMaxChangedFraction);
}

}  // namespace
}  // namespace urdfsnap
