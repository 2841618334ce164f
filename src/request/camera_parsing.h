// The camera options of a request (--camera-info, --camera-frame, --camera-pose, --near, --far,
// --distort, --underlay, --underlay-alpha) checked and made into render::CameraSettings.
#pragma once

#include <optional>

#include "render/render_settings.h"
#include "request/render_request.h"
#include "request/settings_parsing.h"

namespace urdfsnap::request {

// The camera `request` asks for, or nullopt when it names none (no --camera-info, --camera-frame
// or --camera-pose). Without --camera-info the camera has square pixels, the principal point at
// the centre and `settings.view`'s field of view at `settings.size`; with it, `settings.size`
// becomes the file's. Reads the camera info and underlay files. Throws urdfsnap::Error naming the
// option through `label` for a bad value, a camera option without a camera, --distort without
// --camera-info, --fit with a camera, or an unreadable file (located in it).
std::optional<render::CameraSettings> ParseCameraSettings(const RenderRequest& request, const OptionLabel& label,
                                                          render::RenderSettings& settings);

}  // namespace urdfsnap::request
