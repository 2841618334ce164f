// A prepared robot drawn with message displays (display/display_set.h) of message files: the robot
// posed, the displays' items added in the fixed frame, one frame drawn. Frames the displays name are
// the robot's links posed as drawn (a message file's markers on a link follow the link). A
// recording's displays are drawn by animation::FrameDisplays.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "display/display_set.h"
#include "display/marker_shapes.h"
#include "request/render_session.h"

namespace urdfsnap::request {

// MESH_RESOURCE files found as the robot's mesh URIs are (package://, file://, paths; the packages
// and model file of `options`) and loaded as robot meshes are.
display::MarkerResources MarkerResourcesFor(const scene::SceneOptions& options);

// Each link of `robot` in the fixed frame (link `fixed_link`) for link poses X_RL; other frames
// unknown. The pose is the same at every time.
display::FrameLookup RobotFrames(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_RL,
                                 int fixed_link);

// Draws `prepared` (through its orbit view or its calibrated camera) with what `displays` show at
// time 0, their frames among the robot's links. Display problems are warnings.
image::Frame DrawWithDisplays(RenderSession& session, const Prepared& prepared,
                              const display::DisplaySet& displays, Warnings& warnings,
                              const image::FrameOutputs& outputs = {});

}  // namespace urdfsnap::request
