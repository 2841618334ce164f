// Text to typed settings, once per request: RViz's defaults, then the request's .rviz file, then
// the options given (checked: ranges, colours, sizes), as render::RenderSettings. The files are
// read by ReadBaseSettings (.rviz) and ReadCameraFiles (camera_parsing.h) and the options applied
// by ApplyOptions, which reads none, so that a caller who renders many requests over the same
// files (the live view) reads them once.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "common/warnings.h"
#include "render/render_settings.h"
#include "request/render_request.h"

namespace urdfsnap::request {

struct CameraFiles;  // camera_parsing.h

// How error messages name option `name` ("yaw"): "--yaw" on the command line, "suite.yaml:12: yaw"
// for a suite case.
using OptionLabel = std::function<std::string(std::string_view name)>;

// The command line's label: "--" + name. Every command and the live view name options by it.
std::string CommandLineLabel(std::string_view name);

// --fit as a render::Fit: kNone without --fit, kKeepFocal when --focal is given too (the focal
// point stays, the distance frames the robot), else kFit.
render::Fit FitOf(const RenderRequest& request);

// RViz's defaults with the request's .rviz file applied (its warnings go to `warnings`); RViz's
// defaults alone when no .rviz file is named. Throws urdfsnap::Error for an unreadable .rviz file.
render::RenderSettings ReadBaseSettings(const RenderRequest& request, Warnings& warnings);

// Applies the request's option texts over `settings` (RViz's defaults or a .rviz file's): size,
// view, displays, multisampling, --fit; the model file and packages become the scene's places to
// find meshes; the camera options over `camera_files` (ReadCameraFiles of the same request). Reads
// no file. Throws urdfsnap::Error for a bad option value, named through `label`.
void ApplyOptions(const RenderRequest& request, const CameraFiles& camera_files, const OptionLabel& label,
                  render::RenderSettings& settings);

// Warns of options the request gives that have no effect (--distance with --fit).
void WarnOfOptionsWithoutEffect(const RenderRequest& request, const OptionLabel& label, Warnings& warnings);

// ReadBaseSettings and ReadCameraFiles, then ApplyOptions and WarnOfOptionsWithoutEffect: the
// settings `request` asks for.
render::RenderSettings ParseRenderSettings(const RenderRequest& request, const OptionLabel& label,
                                           Warnings& warnings);

}  // namespace urdfsnap::request
