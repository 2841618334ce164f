// CameraInfo files in both ROS layouts, and their errors located at the offending key.
#include <gtest/gtest.h>

#include "camera/camera_info.h"
#include "support/error_text.h"

namespace urdfsnap::camera {
namespace {

using test::ErrorText;

// as ROS's camera_calibration writes ost.yaml
constexpr const char* kCalibrationFile = R"(image_width: 640
image_height: 480
camera_name: narrow_stereo
camera_matrix:
  rows: 3
  cols: 3
  data: [520.5, 0, 301.25, 0, 515.25, 247.75, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.28, 0.09, 0.0012, -0.0007, -0.015]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
projection_matrix:
  rows: 3
  cols: 4
  data: [450.0, 0, 310.5, 0, 0, 455.0, 240.5, 0, 0, 0, 1, 0]
)";

// as `ros2 topic echo /camera/camera_info --once` prints it
constexpr const char* kRos2Message = R"(header:
  stamp:
    sec: 1700000000
    nanosec: 5
  frame_id: camera_optical_frame
height: 480
width: 640
distortion_model: rational_polynomial
d:
- 0.35
- -0.12
- 0.0011
- 0.0009
- 0.02
- 0.62
- -0.08
- 0.03
k:
- 520.5
- 0.0
- 301.25
- 0.0
- 515.25
- 247.75
- 0.0
- 0.0
- 1.0
r: [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
p: [520.5, 0.0, 301.25, -41.64, 0.0, 515.25, 247.75, 0.0, 0.0, 0.0, 1.0, 0.0]
binning_x: 0
binning_y: 0
roi:
  x_offset: 0
  y_offset: 0
  height: 0
  width: 0
  do_rectify: false
---
)";

TEST(CameraInfo, ReadsCameraCalibrationFiles) {
  const CameraInfo info = ParseCameraInfo(kCalibrationFile, "ost.yaml");
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_EQ(info.D.size(), 5u);
  EXPECT_DOUBLE_EQ(info.distortion.k[4], -0.015);
  EXPECT_DOUBLE_EQ(info.distortion.k[5], 0);
  const Intrinsics raw = info.RawIntrinsics();
  EXPECT_DOUBLE_EQ(raw.fx, 520.5);
  EXPECT_DOUBLE_EQ(raw.fy, 515.25);
  EXPECT_DOUBLE_EQ(raw.cx, 301.25);
  EXPECT_DOUBLE_EQ(raw.cy, 247.75);
  const Intrinsics rectified = info.RectifiedIntrinsics();
  EXPECT_DOUBLE_EQ(rectified.fx, 450);
  EXPECT_DOUBLE_EQ(rectified.fy, 455);
  EXPECT_DOUBLE_EQ(rectified.cx, 310.5);
  EXPECT_DOUBLE_EQ(rectified.cy, 240.5);
  EXPECT_EQ(info.frame_id, "");
}

TEST(CameraInfo, ReadsCameraInfoMessages) {
  const CameraInfo info = ParseCameraInfo(kRos2Message, "info.yaml");
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_EQ(info.distortion_model, "rational_polynomial");
  EXPECT_DOUBLE_EQ(info.distortion.k[7], 0.03);
  EXPECT_DOUBLE_EQ(info.P(0, 3), -41.64);
  EXPECT_EQ(info.frame_id, "camera_optical_frame");
}

TEST(CameraInfo, ReadsRos1MessagesAndUncalibratedProjections) {
  // rostopic echo spells the matrices in capitals; an all-zero P means "use K"
  const CameraInfo info = ParseCameraInfo(
      "height: 4\nwidth: 6\ndistortion_model: ''\nD: []\nK: [10, 0, 2.5, 0, 12, 1.5, 0, 0, 1]\n"
      "R: [1, 0, 0, 0, 1, 0, 0, 0, 1]\nP: [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n",
      "ros1.yaml");
  EXPECT_FALSE(info.distortion.Any());
  EXPECT_DOUBLE_EQ(info.RectifiedIntrinsics().fx, 10);
  EXPECT_DOUBLE_EQ(info.RectifiedIntrinsics().cy, 1.5);
}

TEST(CameraInfo, ErrorsNameTheFileLineAndKey) {
  const auto error = [](const std::string& text) {
    return ErrorText([&] { ParseCameraInfo(text, "cam.yaml"); });
  };
  const std::string k = "k: [10, 0, 2.5, 0, 12, 1.5, 0, 0, 1]\n";
  EXPECT_EQ(error("height: 4\n" + k), "cam.yaml: missing 'image_width' (the image size)");
  EXPECT_EQ(error("width: 6.5\nheight: 4\n" + k),
            "cam.yaml:1: width: expected a whole number of pixels from 1 to 16384, got 6.5");
  EXPECT_EQ(error("width: 6\nheight: 4\n"), "cam.yaml: missing 'camera_matrix'");
  EXPECT_EQ(error("width: 6\nheight: 4\nk: [1, 2]\n"),
            "cam.yaml:3: k: expected 9 numbers (3x3, row-major), got 2");
  EXPECT_EQ(error("width: 6\nheight: 4\nk: [1, 0, 0, 0, 1, 0, 0, 0, x]\n"),
            "cam.yaml:3: k: expected a finite number, got 'x'");
  EXPECT_EQ(error("width: 6\nheight: 4\nk: [0, 0, 2.5, 0, 12, 1.5, 0, 0, 1]\n"),
            "cam.yaml:3: k: the focal lengths fx and fy must be positive, got 0 and 12");
  EXPECT_EQ(error("width: 6\nheight: 4\n" + k + "distortion_model: equidistant\nd: [0.1, 0.2, 0.3, 0.4]\n"),
            "cam.yaml:4: distortion model 'equidistant' is not supported (plumb_bob, rational_polynomial)");
  EXPECT_EQ(error("width: 6\nheight: 4\n" + k + "distortion_model: plumb_bob\nd: [0.1, 0.2, 0.3]\n"),
            "cam.yaml:4: plumb_bob takes 5 coefficients (k1, k2, p1, p2, k3), got 3");
  EXPECT_EQ(error("camera_matrix:\n  rows: 3\n  data: 7\n"), "cam.yaml: missing 'image_width' (the image size)");
  EXPECT_EQ(error("image_width: 6\nimage_height: 4\ncamera_matrix:\n  rows: 3\n  data: 7\n"),
            "cam.yaml:4: camera_matrix: expected a list of numbers under 'data'");
  EXPECT_EQ(error("[1, 2]"),
            "cam.yaml: expected a camera calibration (image_width, camera_matrix, ...) or a CameraInfo "
            "message (width, k, ...)");
  EXPECT_EQ(error("width: [6\n"), "cam.yaml:2: bad YAML: end of sequence flow not found");
}

TEST(CameraInfo, UnreadableFilesAreErrors) {
  EXPECT_EQ(ErrorText([] { ReadCameraInfo("/nonexistent/cam.yaml"); }),
            "/nonexistent/cam.yaml: cannot read the camera info: No such file or directory");
}

}  // namespace
}  // namespace urdfsnap::camera
