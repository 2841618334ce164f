// render::OrbitCamera: RViz's orbit view as a camera puts every point on the pixel the orbit view's
// own GL matrices put it on, so keypoints of an orbit render match its pixels.
#include <gtest/gtest.h>

#include "camera/pinhole.h"
#include "render/camera_settings.h"

namespace urdfsnap::render {
namespace {

TEST(OrbitCamera, ProjectsAsTheOrbitView) {
  scene::OrbitView view;
  view.yaw = 0.6;
  view.pitch = 0.35;
  view.distance = 4.5;
  view.focal = Eigen::Vector3d(0.2, -0.1, 1.2);
  const int width = 320, height = 200;
  const CameraSettings camera = OrbitCamera(view, width, height);
  const Eigen::Matrix4d PV = scene::ProjectionMatrix(view, double(width) / height) * scene::ViewMatrix(view);
  for (const Eigen::Vector3d& p_F : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, -0.7, 1.9), Eigen::Vector3d(-1, 1, 0.3)}) {
    const Eigen::Vector4d clip = PV * p_F.homogeneous();
    const Eigen::Vector2d gl_pixel((clip.x() / clip.w() + 1) / 2 * width - 0.5, (1 - clip.y() / clip.w()) / 2 * height - 0.5);
    const std::optional<Eigen::Vector2d> uv = camera.model->Project(camera.model->Pose(camera.pose).inverse() * p_F);
    ASSERT_TRUE(uv);
    EXPECT_NEAR((*uv - gl_pixel).norm(), 0, 1e-9);
  }
  EXPECT_NEAR((camera.pose.translation() - scene::EyePosition(view)).norm(), 0, 1e-12);
  EXPECT_EQ(camera.model->width(), width);
  EXPECT_DOUBLE_EQ(camera.model->clipping().near, view.near_clip);
}

}  // namespace
}  // namespace urdfsnap::render
