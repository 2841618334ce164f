// `GET /api/view`: where the page's controls start (the view and display options `urdfsnap serve`
// was given, over the .rviz file's and RViz's defaults, --fit resolved to a distance and focal
// point) and what a snapshot-suite case of the page's view must carry besides the page's own keys
// (the model and the server's other options).
#pragma once

#include <string>

#include "render/render_settings.h"
#include "request/render_request.h"

namespace urdfsnap::serve {

// JSON: {"options": {size, yaw, pitch, distance, focal, alpha, background as text; fit, no-grid,
// tf, collision, no-visual as booleans}, "size_given": whether a size other than the default was
// asked for (else the page's frame follows its window), "fov": radians, "joints": {NAME: value} (the -j and
// --joints values given), "case": {"model", "args", "packages", "xacro-ns", "options"}} with
// absolute paths in "case". `settings` are those `base` renders with, the view fitted.
// Throws urdfsnap::Error for an unreadable joint file.
std::string InitialViewJson(const request::RenderRequest& base, const render::RenderSettings& settings);

}  // namespace urdfsnap::serve
