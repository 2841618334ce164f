// Text to typed settings, once per request: RViz's defaults, then the request's .rviz file, then
// the options given (checked: ranges, colours, sizes), as render::RenderSettings.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "common/warnings.h"
#include "render/render_settings.h"
#include "request/render_request.h"

namespace urdfsnap::request {

// How error messages name option `name` ("yaw"): "--yaw" on the command line, "suite.yaml:12: yaw"
// for a suite case.
using OptionLabel = std::function<std::string(std::string_view name)>;

// The settings `request` asks for. Reads the .rviz file if one is named (its warnings go to
// `warnings`); the model file and packages become the scene's places to find meshes. Throws
// urdfsnap::Error for a bad option value, named through `label`, or an unreadable .rviz file.
render::RenderSettings ParseRenderSettings(const RenderRequest& request, const OptionLabel& label,
                                           Warnings& warnings);

}  // namespace urdfsnap::request
