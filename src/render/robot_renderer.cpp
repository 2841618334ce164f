// RobotRenderer: forward kinematics and the prepared scene per frame, drawn by a gl::SceneRenderer.
#include "render/robot_renderer.h"

#include "camera/underlay.h"
#include "common/error.h"
#include "model/forward_kinematics.h"
#include "scene/view_fitting.h"

namespace urdfsnap::render {

RobotRenderer::RobotRenderer(std::shared_ptr<const model::Robot> robot, scene::SceneOptions options,
                             Warnings& warnings)
    : robot_(std::move(robot)), scene_(*robot_, std::move(options), warnings) {}

scene::Scene RobotRenderer::Pose(const std::vector<double>& positions, const Eigen::Isometry3d& X_SF) const {
  return scene_.Pose(model::ComputeLinkPoses(*robot_, positions), X_SF);
}

image::Frame RobotRenderer::Render(gl::SceneRenderer& gl, const std::vector<double>& positions,
                                   const scene::OrbitView& view, ImageSize size,
                                   const image::FrameOutputs& outputs, const Eigen::Isometry3d& X_SF) const {
  return gl.Render(Pose(positions, X_SF), view, size.width, size.height, outputs);
}

Eigen::Isometry3d RobotRenderer::CameraPose(const std::vector<Eigen::Isometry3d>& X_RL,
                                            const CameraSettings& camera) const {
  int link = scene_.fixed_link();
  if (!camera.frame.empty()) {
    link = robot_->FindLink(camera.frame);
    if (link < 0) {
      throw Error("camera frame '" + camera.frame + "' is not a link of robot '" + robot_->name() + "'");
    }
  }
  const Eigen::Isometry3d X_FL = X_RL[scene_.fixed_link()].inverse() * X_RL[link];
  return camera.model->Pose(X_FL * camera.pose);
}

image::Frame RobotRenderer::Render(gl::SceneRenderer& gl, const std::vector<double>& positions,
                                   const CameraSettings& camera, const image::FrameOutputs& outputs) const {
  return Render(gl, Pose(positions), Eigen::Isometry3d::Identity(), positions, camera, outputs);
}

image::Frame RobotRenderer::Render(gl::SceneRenderer& gl, const scene::Scene& scene, const Eigen::Isometry3d& X_SF,
                                   const std::vector<double>& positions, const CameraSettings& camera,
                                   const image::FrameOutputs& outputs) const {
  const std::vector<Eigen::Isometry3d> X_RL = model::ComputeLinkPoses(*robot_, positions);
  const camera::CameraModel& model = *camera.model;
  const bool underlay = camera.underlay && outputs.colour;
  image::FrameOutputs wanted = outputs;
  wanted.labels = outputs.labels || underlay;
  const Eigen::Matrix4d view = camera::GlViewMatrix(X_SF * CameraPose(X_RL, camera));
  image::Frame drawn = gl.Render(scene, view, model.GlProjection(), model.drawn().width, model.drawn().height, wanted);
  if (!underlay) return model.Finish(std::move(drawn));
  // the drawn pixels go through the camera's distortion as the labels do (nearest, nothing outside)
  image::LabelImage shown = model.Finish({{}, {}, camera::DrawnPixels(drawn, scene.background)}).labels;
  if (!outputs.labels) drawn.labels = {};
  image::Frame frame = model.Finish(std::move(drawn));
  camera::DrawUnderlay(*camera.underlay, camera.underlay_file, camera.overlay_alpha, shown, frame.colour);
  return frame;
}

image::Frame RobotRenderer::Render(gl::SceneRenderer& gl, const std::vector<double>& positions,
                                   const RenderSettings& settings, const image::FrameOutputs& outputs) const {
  if (settings.camera) return Render(gl, positions, *settings.camera, outputs);
  return Render(gl, positions, settings.view, settings.size, outputs);
}

scene::OrbitView RobotRenderer::FitView(Fit fit, const FitMargin& margin, const scene::OrbitView& view, ImageSize size, int count,
                                        const std::function<std::vector<double>(int)>& pose,
                                        const std::function<Eigen::Isometry3d(int)>& place) const {
  if (fit == Fit::kNone) return view;
  const double aspect = static_cast<double>(size.width) / size.height;
  return scene::FitView(
      count, [&](int k) { return Pose(pose(k), place ? place(k) : Eigen::Isometry3d::Identity()); }, view,
      aspect, fit == Fit::kKeepFocal, margin.For(size));
}

}  // namespace urdfsnap::render
