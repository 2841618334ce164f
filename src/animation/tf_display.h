// RViz's TF display over a recording: the frames of motion::TfDisplayFrames (the robot's links and
// the bag's other TF frames) drawn into a robot's scene with their axes, names and parent arrows,
// the names laid out once.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "motion/tf_display_frames.h"
#include "render/robot_renderer.h"
#include "scene/scene.h"
#include "scene/tf_markers.h"

namespace urdfsnap::animation {

class TfDisplay {
 public:
  // Lays out the frame names when `options` shows them. Throws urdfsnap::Error when the font is
  // missing.
  TfDisplay(motion::TfDisplayFrames frames, scene::TfOptions options);

  // Adds the frames at trajectory time `t` to `scene`, the scene `robot` made for `positions` with
  // its fixed link placed at X_SF (render::RobotRenderer::Pose).
  void AddTo(const render::RobotRenderer& robot, const std::vector<double>& positions,
             const Eigen::Isometry3d& X_SF, double t, scene::Scene& scene, Warnings& warnings) const;

 private:
  motion::TfDisplayFrames frames_;
  scene::TfOptions options_;
  std::vector<scene::TextLabel> names_;
};

}  // namespace urdfsnap::animation
