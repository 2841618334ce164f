// `render` through a calibrated camera, against geometry computed by hand: a 0.4 x 0.2 x 0.3 m box
// seen straight down from 2 m by an off-centre camera with non-square pixels; its silhouette,
// depth and keypoints, the lens remap, the underlay and the mask, a marker drawn through the
// camera; and the camera options' errors.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "camera/distortion.h"
#include "camera/pinhole.h"
#include "cli/cli_fixture.h"
#include "image/png_reader.h"

namespace urdfsnap::cli_test {
namespace {

constexpr const char* kBoxRobot = R"(<robot name="box">
  <link name="body"><visual><geometry><box size="0.4 0.2 0.3"/></geometry></visual></link>
  <link name="tip"/>
  <joint name="body_tip" type="fixed"><parent link="body"/><child link="tip"/>
    <origin xyz="0.2 0.1 0.15"/></joint>
</robot>
)";

// fx 500, fy 400, principal point (200.3, 90.7) in a 400x240 image
constexpr const char* kCameraInfo = R"(image_width: 400
image_height: 240
camera_matrix: {rows: 3, cols: 3, data: [500, 0, 200.3, 0, 400, 90.7, 0, 0, 1]}
distortion_model: plumb_bob
distortion_coefficients: {rows: 1, cols: 5, data: [-0.25, 0.08, 0.001, -0.002, 0.0]}
projection_matrix: {rows: 3, cols: 4, data: [500, 0, 200.3, 0, 0, 400, 90.7, 0, 0, 0, 1, 0]}
)";
const camera::Intrinsics kK{500, 400, 200.3, 90.7};

// 2 m above the box's centre, looking straight down: optical x = +x, y = −y, z = −z
constexpr const char* kLookingDown = "--camera-pose 0,0,2,1,0,0,0 --no-grid";
constexpr double kTopDistance = 2 - 0.15;

class CameraTest : public CliTest {
 protected:
  std::string Render(const std::string& options) {
    const Result r = RunUrdfsnap("render " + Write("box.urdf", kBoxRobot) + " --camera-info " +
                                 Write("cam.yaml", kCameraInfo) + " " + kLookingDown + " -o " + Path("c.png") +
                                 " --labels " + Path("l.png") + " --depth " + Path("d.png") + " " + options);
    EXPECT_EQ(r.status, 0) << r.output;
    return r.output;
  }
  // a plain blue (0,0,200) camera image of the calibration's size, made by rendering an empty view
  std::string BlueImage() {
    const Result blank = RunUrdfsnap("render " + Write("box.urdf", kBoxRobot) + " --no-grid --no-visual --size 400x240 "
                                     "--background 0,0,200 -o " + Path("blue.png"));
    EXPECT_EQ(blank.status, 0) << blank.output;
    return Path("blue.png");
  }
  // whether the ray of normalised image point `p` meets the box's top face
  static bool OnTop(const Eigen::Vector2d& p) {
    return std::abs(p.x() * kTopDistance) < 0.2 && std::abs(p.y() * kTopDistance) < 0.1;
  }
};

TEST_F(CameraTest, SilhouetteAndDepthAreThePinholeProjection) {
  URDFSNAP_REQUIRE_GL();
  Render("");
  const image::Gray16Image labels = image::ReadGray16Png(Path("l.png"));
  const image::Gray16Image depth = image::ReadGray16Png(Path("d.png"));
  ASSERT_EQ(labels.width, 400);
  ASSERT_EQ(labels.height, 240);
  // a pixel is the box's exactly when its centre's ray meets the top face (u = fx·x/z + cx): the
  // corners ±0.2, ±0.1 at 1.85 m give u in (146.25, 254.35), v in (69.08, 112.32)
  int box_pixels = 0;
  for (int v = 0; v < labels.height; ++v) {
    for (int u = 0; u < labels.width; ++u) {
      const size_t i = static_cast<size_t>(v) * labels.width + u;
      const bool expected = OnTop(camera::FromPixel(kK, {u, v}));
      EXPECT_EQ(labels.values[i] != 0, expected) << u << "," << v;
      if (expected) {
        EXPECT_EQ(depth.values[i], 1850) << u << "," << v;   // mm along the optical axis
        ++box_pixels;
      }
    }
  }
  EXPECT_EQ(box_pixels, (254 - 147 + 1) * (112 - 70 + 1));
}

TEST_F(CameraTest, DistortedSilhouetteFollowsTheLens) {
  URDFSNAP_REQUIRE_GL();
  Render("--distort");
  const image::Gray16Image labels = image::ReadGray16Png(Path("l.png"));
  std::string why;
  const camera::Distortion lens =
      *camera::MakeDistortion("plumb_bob", {-0.25, 0.08, 0.001, -0.002, 0.0}, why);
  // each raw pixel shows what lies on its undistorted ray; the remap takes labels from the nearest
  // pinhole pixel, so only pixels whose ray passes within a pixel of the outline may differ
  int wrong = 0, box_pixels = 0;
  for (int v = 0; v < labels.height; ++v) {
    for (int u = 0; u < labels.width; ++u) {
      const std::optional<Eigen::Vector2d> ray = camera::Undistort(lens, camera::FromPixel(kK, {u, v}));
      ASSERT_TRUE(ray);
      const bool expected = OnTop(*ray);
      const bool near_edge = OnTop(*ray + Eigen::Vector2d(1.0 / 500, 1.0 / 400)) != expected ||
                             OnTop(*ray - Eigen::Vector2d(1.0 / 500, 1.0 / 400)) != expected ||
                             OnTop(*ray + Eigen::Vector2d(1.0 / 500, -1.0 / 400)) != expected ||
                             OnTop(*ray - Eigen::Vector2d(1.0 / 500, -1.0 / 400)) != expected;
      const bool got = labels.values[static_cast<size_t>(v) * labels.width + u] != 0;
      if (got != expected && !near_edge) ++wrong;
      box_pixels += got;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(box_pixels, 4000);
}

TEST_F(CameraTest, KeypointsAreProjectedPixelsWithVisibility) {
  URDFSNAP_REQUIRE_GL();
  Render("--distort --keypoints " + Path("k.json"));
  const nlohmann::json k = nlohmann::json::parse(ReadBytes(Path("k.json")));
  EXPECT_EQ(k["camera"]["width"], 400);
  EXPECT_EQ(k["camera"]["K"], nlohmann::json({500.0, 0.0, 200.3, 0.0, 400.0, 90.7, 0.0, 0.0, 1.0}));
  EXPECT_EQ(k["camera"]["D"], nlohmann::json({-0.25, 0.08, 0.001, -0.002, 0.0}));
  EXPECT_EQ(k["camera"]["distortion_model"], "plumb_bob");
  EXPECT_EQ(k["camera"]["pose"], nlohmann::json({0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0}));
  ASSERT_EQ(k["frames"].size(), 3u);   // two links, then one joint
  // the tip (0.2, 0.1, 0.15) is at optical (0.2, −0.1, 1.85): u = fx·x'/z + cx after distortion
  std::string why;
  const camera::Distortion lens = *camera::MakeDistortion("plumb_bob", {-0.25, 0.08, 0.001, -0.002, 0.0}, why);
  const Eigen::Vector2d tip = camera::ToPixel(kK, camera::Distort(lens, {0.2 / 1.85, -0.1 / 1.85}));
  const nlohmann::json& frame = k["frames"][1];
  EXPECT_EQ(frame["name"], "tip");
  EXPECT_EQ(frame["kind"], "link");
  EXPECT_NEAR(frame["u"].get<double>(), tip.x(), 1e-9);
  EXPECT_NEAR(frame["v"].get<double>(), tip.y(), 1e-9);
  EXPECT_NEAR(frame["depth"].get<double>(), 1.85, 1e-12);
  EXPECT_EQ(frame["in_image"], true);
  EXPECT_EQ(frame["visible"], true);
  // the body's origin is inside the box: hidden by nothing but its own link
  EXPECT_EQ(k["frames"][0]["visible"], true);
  EXPECT_EQ(k["frames"][2]["name"], "body_tip");
  EXPECT_EQ(k["frames"][2]["kind"], "joint");
}

TEST_F(CameraTest, UnderlayShowsBehindAndThroughTheRobot) {
  URDFSNAP_REQUIRE_GL();
  Render("--underlay " + BlueImage() + " --underlay-alpha 0.25 --mask " + Path("m.png") + " --mask-dilate 3");
  const image::Image c = image::ReadPng(Path("c.png"));
  const image::Gray16Image labels = image::ReadGray16Png(Path("l.png"));
  const image::Image mask = image::ReadPng(Path("m.png"));
  int grown = 0;
  const auto by_the_box = [&](size_t i) {   // the box's anti-aliased edge, drawn on and so blended
    const int x = static_cast<int>(i % labels.width), y = static_cast<int>(i / labels.width);
    for (int v = std::max(y - 1, 0); v <= std::min(y + 1, labels.height - 1); ++v) {
      for (int u = std::max(x - 1, 0); u <= std::min(x + 1, labels.width - 1); ++u) {
        if (labels.values[static_cast<size_t>(v) * labels.width + u] != 0) return true;
      }
    }
    return false;
  };
  for (size_t i = 0; i < labels.values.size(); ++i) {
    if (labels.values[i] == 0) {
      if (!by_the_box(i)) {
        EXPECT_EQ(c.rgb[i * 3 + 2], 200);
      }
      grown += mask.rgb[i * 3] == 255;
    } else {
      EXPECT_GE(c.rgb[i * 3 + 2], 50);   // a quarter of the blue through the red box
      EXPECT_GT(c.rgb[i * 3], 100);
      EXPECT_EQ(mask.rgb[i * 3], 255);
    }
  }
  // three pixels around the 108 x 43 rectangle, rounded corners
  EXPECT_GT(grown, 2 * 3 * (108 + 43));
  EXPECT_LT(grown, 2 * 3 * (108 + 43) + 4 * 9);
}

TEST_F(CameraTest, ASizeBesideACalibrationIsIgnoredWithAWarning) {
  URDFSNAP_REQUIRE_GL();
  // the calibration's 400x240 either way; only a --size given is warned of, not the default
  EXPECT_EQ(Render(""), "");
  EXPECT_EQ(Render("--size 640x480"),
            "urdfsnap: warning: --size 640x480 is ignored: the size comes from the calibration (--camera-info)\n");
  EXPECT_EQ(image::ReadGray16Png(Path("l.png")).width, 400);
  // animate's size from its output format is no given size either
  const Result animate = RunUrdfsnap("animate " + Write("box.urdf", kBoxRobot) + " --camera-info " +
                                     Path("cam.yaml") + " " + kLookingDown + " --turntable --duration 0.1 --fps 10 -q -o " +
                                     Path("a/%02d.png"));
  EXPECT_EQ(animate.status, 0) << animate.output;
  EXPECT_EQ(animate.output, "");
  EXPECT_EQ(image::ReadGray16Png(Path("a/00.png")).width, 400);
}

// A green sphere 6 cm across at (0.35, 0.25, 0) beside the box, drawn through the camera as a
// message display (`--message`), and the centre of its green pixels: where the sphere's centre
// is in the normalised image, 2 m straight down (optical x = +x, y = −y).
const Eigen::Vector2d kSphereCentre(0.35 / 2, -0.25 / 2);
// a green sphere 6 cm across beside the box, in the body's frame
constexpr const char* kSphereMarker = R"(header: {frame_id: body}
type: 2
pose: {position: {x: 0.35, y: 0.25, z: 0}}
scale: {x: 0.06, y: 0.06, z: 0.06}
color: {g: 1, a: 1}
)";

Eigen::Vector2d GreenCentre(const image::Image& image) {
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

// Message displays are seen through the camera as the robot is: through the rectified P, and with
// --distort through the lens (K and D; tests/camera/projection_test.cpp checks the lens against
// OpenCV's cv2.projectPoints).
TEST_F(CameraTest, AMarkerLandsWhereTheCameraProjectsItsPoint) {
  URDFSNAP_REQUIRE_GL();
  const std::string marker = " --message " + Write("m.yaml", kSphereMarker) + ":visualization_msgs/msg/Marker";
  Render(marker);
  const Eigen::Vector2d pinhole = camera::ToPixel(kK, kSphereCentre);   // P is K here
  EXPECT_LT((GreenCentre(image::ReadPng(Path("c.png"))) - pinhole).norm(), 0.6);
  Render(marker + " --distort");
  std::string why;
  const camera::Distortion lens = *camera::MakeDistortion("plumb_bob", {-0.25, 0.08, 0.001, -0.002, 0.0}, why);
  const Eigen::Vector2d raw = camera::ToPixel(kK, camera::Distort(lens, kSphereCentre));
  EXPECT_LT((GreenCentre(image::ReadPng(Path("c.png"))) - raw).norm(), 0.6);
  EXPECT_GT((raw - pinhole).norm(), 1.2) << "the lens moves it";
}

// RViz's Camera display draws its image over everything the view shows, robot and displays alike:
// the marker is seen through the camera image at the overlay alpha, the image alone elsewhere.
TEST_F(CameraTest, AMarkerShowsOverTheUnderlayAsTheRobotDoes) {
  URDFSNAP_REQUIRE_GL();
  const std::string marker = " --no-grid --message " + Write("m.yaml", kSphereMarker) + ":visualization_msgs/msg/Marker";
  Render(marker);
  const image::Image alone = image::ReadPng(Path("c.png"));
  Render(marker + " --underlay " + BlueImage());
  const image::Image over = image::ReadPng(Path("c.png"));
  const Eigen::Vector2d centre = camera::ToPixel(kK, kSphereCentre);
  const size_t at = static_cast<size_t>(std::lround(centre.y())) * over.width + std::lround(centre.x());
  ASSERT_GT(alone.rgb[at * 3 + 1], 100) << "the marker is drawn there";
  const std::uint8_t blue[3] = {0, 0, 200};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(over.rgb[at * 3 + c], (blue[c] + alone.rgb[at * 3 + c]) / 2.0, 0.5) << c;
  // the image's corner, where nothing is drawn, is the image's own colour
  EXPECT_EQ(std::vector<std::uint8_t>(over.rgb.begin(), over.rgb.begin() + 3), std::vector<std::uint8_t>(blue, blue + 3));
}

TEST_F(CameraTest, CameraOptionErrorsAreOneLine) {
  const std::string model = Write("box.urdf", kBoxRobot) + " -o " + Path("x.png") + " ";
  const std::string info = " --camera-info " + Write("cam.yaml", kCameraInfo);
  const auto error = [](const std::string& arguments) {
    const Result r = RunUrdfsnap("render " + arguments);
    EXPECT_EQ(r.status, 2) << r.output;
    return r.output;
  };
  EXPECT_EQ(error(model + "--distort --camera-pose 0,0,2,1,0,0,0"),
            "urdfsnap: error: --distort needs --camera-info (the lens's distortion coefficients)\n");
  EXPECT_EQ(error(model + "--underlay u.png"),
            "urdfsnap: error: --underlay needs a camera: --camera-info, --camera-frame or --camera-pose\n");
  EXPECT_EQ(error(model + info + " --fit"),
            "urdfsnap: error: --fit frames the orbit view; a camera (--camera-info, --camera-frame, "
            "--camera-pose) is placed as given\n");
  EXPECT_EQ(error(model + info + " --near 2 --far 1"), "urdfsnap: error: --far 1 must be beyond --near 2\n");
  EXPECT_EQ(error(model + info + " --camera-pose 0,0,2,0,0,0,0"),
            "urdfsnap: error: --camera-pose '0,0,2,0,0,0,0': the quaternion QX,QY,QZ,QW is zero\n");
  EXPECT_EQ(error(model + info + " --camera-frame elbow"),
            "urdfsnap: error: camera frame 'elbow' is not a link of robot 'box'\n");
  EXPECT_EQ(error(model + "--camera-info " + Write("bad.yaml", "width: 4\nheight: 3\nk: [1, 2]\n")),
            "urdfsnap: error: " + Path("bad.yaml") + ":3: k: expected 9 numbers (3x3, row-major), got 2\n");
  EXPECT_EQ(error(model + "--mask m.jpg"), "urdfsnap: error: --mask 'm.jpg': expected a .png (8-bit mask) file; urdfsnap does not write .jpg images\n");
  EXPECT_FALSE(std::filesystem::exists(Path("x.png")));
}

}  // namespace
}  // namespace urdfsnap::cli_test
