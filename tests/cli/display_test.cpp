// `render --message` and `--display`: MarkerArrays drawn on mrm and compared with their golden
// images: one marker of each type (tests/golden/every_marker.png) and RViz's looks the public
// reference scenes do not show (marker lists, line alphas, text lines, transparency, tinted meshes:
// tests/golden/marker_looks.png); bad message files and options are errors naming the file and
// line, broken markers warnings naming the marker.
//
// The golden images, after an intended change (look at them before committing), NAME every_marker
// or marker_looks:
//   build/urdfsnap render models/mrm_description/urdf/mrm.urdf --package
//     meshbot_description=models/meshbot_description --message
//     tests/data/markers/NAME.yaml:visualization_msgs/msg/MarkerArray --yaw 0.3 --pitch 0.6
//     --distance 5.5 --focal 0.6,0,0.4 -o tests/golden/NAME.png
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_diff.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

const std::string kView = " --yaw 0.3 --pitch 0.6 --distance 5.5 --focal 0.6,0,0.4";

// Pixels whose channels differ by more than 24 (antialiased edges move a little between Mesa
// builds), as a share of the image.
double ChangedShare(const image::Image& a, const image::Image& b) {
  return image::CompareImages(a, b, 24).fraction_over;
}

class DisplayCliTest : public CliTest {
 protected:
  // Draws tests/data/markers/NAME.yaml on mrm, without a warning, and compares it with
  // tests/golden/NAME.png; the markers are there at all: the robot alone differs in many pixels.
  void ExpectGolden(const std::string& name) {
    const std::string message =
        (kSource / "tests/data/markers" / (name + ".yaml")).string() + ":visualization_msgs/msg/MarkerArray";
    const Result r = RunUrdfsnap("render " + kMrm + " --package meshbot_description=" +
                                 (kSource / "models/meshbot_description").string() + " --message " + message + kView +
                                 " -o " + Path(name + ".png"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, "");   // every marker drawn, no warning
    const image::Image golden = image::ReadPng((kSource / "tests/golden" / (name + ".png")).string());
    const image::Image actual = image::ReadPng(Path(name + ".png"));
    EXPECT_LT(ChangedShare(actual, golden), 0.005);
    ASSERT_EQ(RunUrdfsnap("render " + kMrm + kView + " -o " + Path("robot.png")).status, 0);
    EXPECT_GT(ChangedShare(actual, image::ReadPng(Path("robot.png"))), 0.03);
  }
};

TEST_F(DisplayCliTest, EveryMarkerTypeMatchesItsGolden) {
  URDFSNAP_REQUIRE_GL();
  ExpectGolden("every_marker");
}

TEST_F(DisplayCliTest, RvizLooksBeyondThePublicScenesMatchTheirGolden) {
  URDFSNAP_REQUIRE_GL();
  ExpectGolden("marker_looks");
}

TEST_F(DisplayCliTest, BadMessageFilesAreErrorsAtTheirLine) {
  const std::string bad = Write("bad.yaml", "markers:\n  - ns: a\n    colour: {r: 1}\n");
  Result r = RunUrdfsnap("render " + kMrm + " --message " + bad + ":visualization_msgs/msg/MarkerArray -o " +
                         Path("x.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "urdfsnap: error: " + bad + ":3: 'colour' is not a field of visualization_msgs/Marker\n");
  r = RunUrdfsnap("render " + kMrm + " --message " + bad + ":sensor_msgs/msg/Image -o " + Path("x.png"));
  EXPECT_EQ(r.status, 2);
  // every type a display draws, each a message file may hold
  EXPECT_NE(r.output.find("no display draws messages of type 'sensor_msgs/msg/Image'; urdfsnap draws "
                          "visualization_msgs/msg/Marker, visualization_msgs/msg/MarkerArray, nav_msgs/msg/Path, "
                          "geometry_msgs/msg/PoseArray, sensor_msgs/msg/PointCloud2, sensor_msgs/msg/LaserScan\n"),
            std::string::npos) << r.output;
  r = RunUrdfsnap("render " + kMrm + " --display Map:/map -o " + Path("x.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("unknown display class 'Map'"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(Path("x.png")));
}

TEST_F(DisplayCliTest, ALaserScanMessageFileIsDrawn) {
  URDFSNAP_REQUIRE_GL();
  // 90 ranges of 1.5 m over a half turn, in FlatColor's default white
  std::string ranges;
  for (int i = 0; i < 90; ++i) ranges += std::string(i ? ", " : "") + "1.5";
  const std::string scan = Write("scan.yaml", "header: {frame_id: base_link}\nangle_min: -1.5708\nangle_max: 1.5708\n"
                                              "angle_increment: 0.0353\nrange_min: 0.1\nrange_max: 10\nranges: [" +
                                                  ranges + "]\n");
  const Result r = RunUrdfsnap("render " + kMrm + " --message " + scan + ":sensor_msgs/msg/LaserScan" + kView + " -o " +
                               Path("scan.png"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "");
  ASSERT_EQ(RunUrdfsnap("render " + kMrm + kView + " -o " + Path("robot.png")).status, 0);
  // RViz's default Flat Squares of 0.01 m: a half ring of 90 dots of a few pixels each
  EXPECT_GT(ChangedShare(image::ReadPng(Path("scan.png")), image::ReadPng(Path("robot.png"))) * 640 * 480, 150);
}

TEST_F(DisplayCliTest, BrokenMarkersAreWarningsNamingThemAndTheRestIsDrawn) {
  URDFSNAP_REQUIRE_GL();
  const std::string markers = Write("m.yaml", R"(markers:
  - {ns: nan, id: 1, type: 1, pose: {position: {x: .nan}}, scale: {x: 1, y: 1, z: 1}}
  - {ns: mesh, id: 2, type: 10, mesh_resource: "package://nowhere/m.stl", scale: {x: 1, y: 1, z: 1}}
  - {ns: lost, id: 3, type: 1, header: {frame_id: nowhere}, scale: {x: 1, y: 1, z: 1}}
  - {ns: ok, id: 4, type: 2, header: {frame_id: base_link}, scale: {x: 1, y: 1, z: 1}, color: {g: 1, a: 1}}
)");
  const Result r = RunUrdfsnap("render " + kMrm + " --message " + markers +
                               ":visualization_msgs/msg/MarkerArray -o " + Path("m.png"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: " + markers + ": marker 'nan/1': contains invalid floating point values"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find("warning: " + markers + ": marker 'mesh/2': "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("warning: " + markers + ": marker 'lost/3': no transform from frame 'nowhere'"),
            std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(Path("m.png")));
}

}  // namespace
}  // namespace urdfsnap::cli_test
