// The one camera of a turntable, shared by `animate --turntable --fit` and the docs page's
// turntable: the focal point stays put while the yaw turns, and the distance is the least that
// frames the robot from every side it is seen from.
#pragma once

#include <functional>
#include <vector>

#include "render/render_settings.h"
#include "render/robot_renderer.h"
#include "scene/orbit_view.h"

namespace urdfsnap::render {

// The view of frame 0 of a turntable of `count` frames, frame k showing pose(k) from yaw(k) (the
// caller turns the returned view's yaw per frame). The focal point is the centre of the bounds of
// every frame (the vertical axis it turns about passes through the robot's middle), or the given
// one with Fit::kKeepFocal; then each frame is fitted from its own yaw around that focal point,
// leaving `margin`, and the largest distance kept. With Fit::kNone the view is `view` as given.
// The poses (placed at `place(k)` when given, as RobotRenderer::FitView takes them) are asked for
// several times and not kept.
scene::OrbitView FitTurntable(const RobotRenderer& robot, Fit fit, const FitMargin& margin,
                              const scene::OrbitView& view, ImageSize size, int count,
                              const std::function<std::vector<double>(int)>& pose,
                              const std::function<double(int)>& yaw,
                              const std::function<Eigen::Isometry3d(int)>& place = {});

}  // namespace urdfsnap::render
