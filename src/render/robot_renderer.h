// The typed render core that C++ users link and every command uses: a robot prepared once
// (meshes, textures, colours, TF names: scene::RobotScene), then one call per frame with joint
// positions, view, image size and the outputs wanted, doing no file I/O. The GL side (a context
// and its uploaded meshes) is a gl::SceneRenderer the caller owns and may share between robots.
//
//   auto robot = std::make_shared<const model::Robot>(model::LoadRobot(urdf, "arm.urdf", warnings));
//   render::RobotRenderer arm(robot, settings.scene, warnings);
//   gl::SceneRenderer gl(settings.samples);
//   for (const auto& positions : poses)
//     image::Frame frame = arm.Render(gl, positions, settings.view, settings.size, {});
#pragma once

#include <memory>
#include <vector>

#include "common/warnings.h"
#include "gl/scene_renderer.h"
#include "image/image.h"
#include "model/robot.h"
#include "render/render_settings.h"
#include "scene/robot_scene.h"

namespace urdfsnap::render {

class RobotRenderer {
 public:
  // Prepares `robot` for `options`. Throws urdfsnap::Error as scene::RobotScene does (files that
  // cannot be found or read, located at the link; an unknown fixed frame; a missing font).
  RobotRenderer(std::shared_ptr<const model::Robot> robot, scene::SceneOptions options, Warnings& warnings);

  const model::Robot& robot() const { return *robot_; }
  const scene::RobotScene& scene() const { return scene_; }

  // The scene for `positions` (one per robot().joints(), radians or metres, mimic joints resolved,
  // as model::ResolveJointPositions returns them), the fixed link placed at X_SF in the scene (see
  // scene::RobotScene::Pose). Throws urdfsnap::Error for a wrong count.
  scene::Scene Pose(const std::vector<double>& positions,
                    const Eigen::Isometry3d& X_SF = Eigen::Isometry3d::Identity()) const;

  // Renders one frame of the robot at `positions` (placed at X_SF) through `gl`.
  image::Frame Render(gl::SceneRenderer& gl, const std::vector<double>& positions, const scene::OrbitView& view,
                      ImageSize size, const image::FrameOutputs& outputs = {},
                      const Eigen::Isometry3d& X_SF = Eigen::Isometry3d::Identity()) const;

  // Renders one frame of the robot at `positions` through a calibrated camera, at the camera's
  // image size: depth along its optical axis, labels from the same pixels, the lens applied when
  // the camera distorts, the camera's underlay (if any) behind everything drawn, which shows
  // over it at the overlay alpha as in RViz's Camera display. Throws urdfsnap::Error
  // for an unknown camera frame, or as gl::SceneRenderer::Render does.
  image::Frame Render(gl::SceneRenderer& gl, const std::vector<double>& positions, const CameraSettings& camera,
                      const image::FrameOutputs& outputs = {}) const;

  // Renders `scene` (the robot at `positions` with its fixed link placed at X_SF, as Pose makes it,
  // with whatever was added to it: message displays, the TF display) through a calibrated camera as
  // the overload above renders the robot alone: the camera placed on the robot as there, so in the
  // scene at X_SF times that, the lens applied to everything drawn.
  image::Frame Render(gl::SceneRenderer& gl, const scene::Scene& scene, const Eigen::Isometry3d& X_SF,
                      const std::vector<double>& positions, const CameraSettings& camera,
                      const image::FrameOutputs& outputs = {}) const;

  // Renders one frame as `settings` ask: through settings.camera when set, else through
  // settings.view at settings.size.
  image::Frame Render(gl::SceneRenderer& gl, const std::vector<double>& positions, const RenderSettings& settings,
                      const image::FrameOutputs& outputs = {}) const;

  // The camera's optical frame in the fixed frame for link poses X_RL (model::ComputeLinkPoses).
  // Throws urdfsnap::Error when camera.frame is not a link of the robot.
  Eigen::Isometry3d CameraPose(const std::vector<Eigen::Isometry3d>& X_RL, const CameraSettings& camera) const;

  // The view `fit` makes of `view`, leaving `margin` on each side, for the poses `pose(k)` (placed at `place(k)` when given),
  // k = 0 .. count-1, as one camera for all of them (an animation's camera does not jump). The
  // poses are asked for twice and not kept.
  scene::OrbitView FitView(Fit fit, const FitMargin& margin, const scene::OrbitView& view, ImageSize size, int count,
                           const std::function<std::vector<double>(int)>& pose,
                           const std::function<Eigen::Isometry3d(int)>& place = {}) const;

 private:
  std::shared_ptr<const model::Robot> robot_;
  scene::RobotScene scene_;
};

}  // namespace urdfsnap::render
