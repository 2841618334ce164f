// Message displays through a calibrated camera, as the robot is seen through it: a sphere marker at a
// known point beside a box, seen straight down from 2 m by an off-centre camera with non-square
// pixels, lands at the pixel the camera's projection gives (the rectified P without --distort; the
// raw K and plumb_bob lens with it, the lens checked against OpenCV's cv2.projectPoints in
// tests/camera/projection_test.cpp).
#include <gtest/gtest.h>

#include "camera/distortion.h"
#include "camera/pinhole.h"
#include "cli/cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

constexpr const char* kBoxRobot = R"(<robot name="box">
  <link name="body"><visual><geometry><box size="0.4 0.2 0.3"/></geometry></visual></link>
</robot>
)";

// K: fx 500, fy 400, principal point (200.3, 90.7); P (the rectified image): fx 480, fy 390, (195.5, 92.25)
constexpr const char* kCameraInfo = R"(image_width: 400
image_height: 240
camera_matrix: {rows: 3, cols: 3, data: [500, 0, 200.3, 0, 400, 90.7, 0, 0, 1]}
distortion_model: plumb_bob
distortion_coefficients: {rows: 1, cols: 5, data: [-0.25, 0.08, 0.001, -0.002, 0.0]}
projection_matrix: {rows: 3, cols: 4, data: [480, 0, 195.5, 0, 0, 390, 92.25, 0, 0, 0, 1, 0]}
)";

// a green sphere 6 cm across at (0.35, 0.25, 0) in the box's frame, beside the box
constexpr const char* kMarker = R"(header: {frame_id: body}
ns: probe
type: 2
pose: {position: {x: 0.35, y: 0.25, z: 0}}
scale: {x: 0.06, y: 0.06, z: 0.06}
color: {g: 1, a: 1}
)";
// where the sphere's centre is in the camera's normalised image: 2 m straight down, optical
// x = +x, y = −y
const Eigen::Vector2d kCentre(0.35 / 2, -0.25 / 2);

class CameraDisplayTest : public CliTest {
 protected:
  // The centre of the green pixels of `render` through the camera with the marker and `options`.
  Eigen::Vector2d GreenCentre(const std::string& options) {
    const Result r = RunUrdfsnap("render " + Write("box.urdf", kBoxRobot) + " --camera-info " +
                                 Write("cam.yaml", kCameraInfo) + " --camera-pose 0,0,2,1,0,0,0 --no-grid --message " +
                                 Write("m.yaml", kMarker) + ":visualization_msgs/msg/Marker -o " + Path("c.png") + " " +
                                 options);
    EXPECT_EQ(r.status, 0) << r.output;
    const image::Image image = image::ReadPng(Path("c.png"));
    Eigen::Vector2d sum(0, 0);
    int count = 0;
    for (int v = 0; v < image.height; ++v) {
      for (int u = 0; u < image.width; ++u) {
        const std::uint8_t* p = &image.rgb[(static_cast<size_t>(v) * image.width + u) * 3];
        if (p[1] > p[0] + 60 && p[1] > p[2] + 60) {
          sum += Eigen::Vector2d(u, v);   // pixel centres at whole numbers, as OpenCV has them
          ++count;
        }
      }
    }
    EXPECT_GT(count, 80) << "the sphere is drawn";
    return count ? Eigen::Vector2d(sum / count) : sum;
  }
};

TEST_F(CameraDisplayTest, AMarkerLandsWhereTheRectifiedProjectionPutsIt) {
  URDFSNAP_REQUIRE_GL();
  const Eigen::Vector2d expected = camera::ToPixel({480, 390, 195.5, 92.25}, kCentre);
  EXPECT_LT((GreenCentre("") - expected).norm(), 0.6) << GreenCentre("").transpose() << " vs " << expected.transpose();
}

TEST_F(CameraDisplayTest, AMarkerLandsWhereTheLensPutsItWithDistort) {
  URDFSNAP_REQUIRE_GL();
  std::string why;
  const camera::Distortion lens = *camera::MakeDistortion("plumb_bob", {-0.25, 0.08, 0.001, -0.002, 0.0}, why);
  const Eigen::Vector2d expected = camera::ToPixel({500, 400, 200.3, 90.7}, camera::Distort(lens, kCentre));
  const Eigen::Vector2d got = GreenCentre("--distort");
  EXPECT_LT((got - expected).norm(), 0.6) << got.transpose() << " vs " << expected.transpose();
}

}  // namespace
}  // namespace urdfsnap::cli_test
