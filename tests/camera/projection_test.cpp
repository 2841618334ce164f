// Pinhole projection and OpenCV's distortion against values OpenCV 4.6's cv2.projectPoints gave
// (Debian's python3-opencv, rvec = tvec = 0), and the GL projection against the pinhole's pixels.
#include <gtest/gtest.h>

#include "camera/camera_model.h"
#include "camera/distortion.h"
#include "camera/pinhole.h"

namespace urdfsnap::camera {
namespace {

const Intrinsics kK{520.5, 515.25, 301.25, 247.75};   // off-centre, non-square pixels
const Eigen::Vector3d kPoints[] = {{0.1, -0.2, 1.5}, {-0.4, 0.3, 2.0}, {0.6, 0.45, 1.2}, {0, 0, 3}};

struct OpenCvCase {
  const char* model;
  std::vector<double> d;
  Eigen::Vector2d expected[4];   // cv2.projectPoints(points, 0, 0, K, D)
};

const OpenCvCase kOpenCvCases[] = {
    {"plumb_bob", {}, {{335.95, 179.05}, {197.15, 325.0375}, {561.5, 440.96875}, {301.25, 247.75}}},
    {"plumb_bob",
     {-0.28, 0.09, 0.0012, -0.0007, -0.015},
     {{335.713186065844, 179.516560641975},
      {198.846137694336, 323.799964851440},
      {536.286190267372, 422.596321116138},
      {301.25, 247.75}}},
    {"rational_polynomial",
     {0.35, -0.12, 0.0011, 0.0009, 0.02, 0.62, -0.08, 0.03},
     {{335.748337045837, 179.482462779568},
      {198.889961540378, 323.802851924858},
      {538.432822943521, 423.928406296674},
      {301.25, 247.75}}},
};

TEST(Projection, MatchesOpenCvProjectPoints) {
  for (const OpenCvCase& c : kOpenCvCases) {
    std::string why;
    const std::optional<Distortion> d = MakeDistortion(c.model, c.d, why);
    ASSERT_TRUE(d) << why;
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d uv = ToPixel(kK, Distort(*d, kPoints[i].head<2>() / kPoints[i].z()));
      EXPECT_NEAR(uv.x(), c.expected[i].x(), 1e-9) << c.model << " point " << i;
      EXPECT_NEAR(uv.y(), c.expected[i].y(), 1e-9) << c.model << " point " << i;
    }
  }
}

TEST(Projection, UndistortInvertsDistort) {
  std::string why;
  const Distortion d = *MakeDistortion("rational_polynomial", kOpenCvCases[2].d, why);
  for (const Eigen::Vector3d& p : kPoints) {
    const Eigen::Vector2d ideal = p.head<2>() / p.z();
    const std::optional<Eigen::Vector2d> back = Undistort(d, Distort(d, ideal));
    ASSERT_TRUE(back);
    EXPECT_NEAR((*back - ideal).norm(), 0, 1e-10);
  }
  // a barrel lens folds over far out: no ideal point maps there
  const Distortion barrel = *MakeDistortion("plumb_bob", {-0.5, 0, 0, 0, 0}, why);
  EXPECT_FALSE(Undistort(barrel, {2.0, 0}));
}

TEST(Projection, GlMatrixPutsPointsOnTheirOpenCvPixels) {
  // the GL projection's normalised device coordinates, read as pixels of a top-row-first image
  // (x = −1 the left edge of column 0, y = +1 the top edge of row 0), are ToPixel's (u, v)
  const int width = 640, height = 480;
  const Eigen::Matrix4d P = GlProjection(kK, width, height, 0.01, 100);
  Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
  X_WC.translation() = Eigen::Vector3d(0.3, -1, 2);
  X_WC.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix4d V = GlViewMatrix(X_WC);
  for (const Eigen::Vector3d& p_C : kPoints) {
    const Eigen::Vector4d clip = P * V * (X_WC * p_C).homogeneous();
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    const Eigen::Vector2d gl_pixel((ndc.x() + 1) / 2 * width - 0.5, (1 - ndc.y()) / 2 * height - 0.5);
    const Eigen::Vector2d cv_pixel = ToPixel(kK, p_C.head<2>() / p_C.z());
    EXPECT_NEAR((gl_pixel - cv_pixel).norm(), 0, 1e-9);
    EXPECT_NEAR(clip.w(), p_C.z(), 1e-12);   // w is the depth along the optical axis
  }
  // near and far map to −1 and +1
  for (const double z : {0.01, 100.0}) {
    const Eigen::Vector4d clip = P * Eigen::Vector4d(0, 0, -z, 1);
    EXPECT_NEAR(clip.z() / clip.w(), z == 100 ? 1 : -1, 1e-9);
  }
}

TEST(Projection, CentredIntrinsicsMatchTheOrbitFieldOfView) {
  const Intrinsics k = CentredIntrinsics(0.785398163397448, 640, 480);
  EXPECT_DOUBLE_EQ(k.cx, 319.5);
  EXPECT_DOUBLE_EQ(k.cy, 239.5);
  EXPECT_NEAR(k.fy, 240 / std::tan(0.785398163397448 / 2), 1e-9);
  EXPECT_DOUBLE_EQ(k.fx, k.fy);
}

TEST(CameraModel, RectifiedUsesPAndItsStereoOffset) {
  CameraInfo info;
  info.width = 640;
  info.height = 480;
  info.K << 520.5, 0, 301.25, 0, 515.25, 247.75, 0, 0, 1;
  info.P << 500, 0, 320, -50, 0, 500, 240, 0, 0, 0, 1, 0;   // a right camera 0.1 m along x
  std::string why;
  info.distortion_model = "plumb_bob";
  info.distortion = *MakeDistortion("plumb_bob", kOpenCvCases[1].d, why);
  const CameraModel rectified(info, false, {});
  EXPECT_DOUBLE_EQ(rectified.intrinsics().fx, 500);
  EXPECT_FALSE(rectified.distortion().Any());
  EXPECT_EQ(rectified.drawn().width, 640);
  EXPECT_NEAR((rectified.Pose(Eigen::Isometry3d::Identity()).translation() - Eigen::Vector3d(0.1, 0, 0)).norm(), 0,
              1e-12);
  const CameraModel raw(info, true, {});
  EXPECT_DOUBLE_EQ(raw.intrinsics().fx, 520.5);
  EXPECT_EQ(raw.distortion_model(), "plumb_bob");
  const std::optional<Eigen::Vector2d> uv = raw.Project(kPoints[1]);
  ASSERT_TRUE(uv);
  EXPECT_NEAR(uv->x(), 198.846137694336, 1e-9);
  EXPECT_FALSE(raw.Project({0, 0, -1}));
  // the drawn pinhole image is wider than the raw one: barrel distortion sees more
  EXPECT_GT(raw.drawn().width, 640);
}

}  // namespace
}  // namespace urdfsnap::camera
