// RobotRenderer: forward kinematics and the prepared scene per frame, drawn by a gl::Renderer.
#include "render/robot_renderer.h"

#include "model/forward_kinematics.h"
#include "scene/view_fitting.h"

namespace urdfsnap::render {

RobotRenderer::RobotRenderer(std::shared_ptr<const model::Robot> robot, scene::SceneOptions options,
                             Warnings& warnings)
    : robot_(std::move(robot)), scene_(*robot_, std::move(options), warnings) {}

scene::Scene RobotRenderer::Pose(const std::vector<double>& positions, const Eigen::Isometry3d& X_SF) const {
  return scene_.Pose(model::ComputeLinkPoses(*robot_, positions), X_SF);
}

image::Frame RobotRenderer::Render(gl::Renderer& gl, const std::vector<double>& positions,
                                   const scene::OrbitView& view, ImageSize size,
                                   const image::FrameOutputs& outputs, const Eigen::Isometry3d& X_SF) const {
  return gl.Render(Pose(positions, X_SF), view, size.width, size.height, outputs);
}

scene::OrbitView RobotRenderer::FitView(Fit fit, const scene::OrbitView& view, ImageSize size, int count,
                                        const std::function<std::vector<double>(int)>& pose,
                                        const std::function<Eigen::Isometry3d(int)>& place) const {
  if (fit == Fit::kNone) return view;
  const double aspect = static_cast<double>(size.width) / size.height;
  return scene::FitView(
      count, [&](int k) { return Pose(pose(k), place ? place(k) : Eigen::Isometry3d::Identity()); }, view,
      aspect, fit == Fit::kKeepFocal);
}

}  // namespace urdfsnap::render
