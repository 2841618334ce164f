// `GET /api/view`: where the page's controls start (the view and display options `urdfsnap serve`
// was given, over the .rviz file's and RViz's defaults) and what a snapshot-suite case of the
// page's view must carry besides the page's own keys (the model and the server's other options).
#pragma once

#include <string>

#include "common/warnings.h"
#include "request/render_request.h"

namespace urdfsnap::serve {

// JSON: {"options": {size, yaw, pitch, distance, focal, alpha, background as text; no-grid, tf,
// collision, no-visual as booleans}, "fov": radians, "joints": {NAME: value} (the -j and --joints
// values given), "case": {"model", "args", "packages", "xacro-ns", "options"}} with absolute
// paths in "case". Throws urdfsnap::Error for an unreadable .rviz or joint file or a bad value.
std::string InitialViewJson(const request::RenderRequest& base, Warnings& warnings);

}  // namespace urdfsnap::serve
