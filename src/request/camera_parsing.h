// The camera options of a request (--camera-info, --camera-frame, --camera-pose, --near, --far,
// --distort, --underlay, --underlay-alpha) checked and made into render::CameraSettings; the files
// they name read once, apart (CameraFiles), so that making the settings reads no file.
#pragma once

#include <memory>
#include <optional>

#include "camera/camera_info.h"
#include "image/image.h"

#include "render/render_settings.h"
#include "request/render_request.h"
#include "request/settings_parsing.h"

namespace urdfsnap::request {

// The files a request's camera options name: --camera-info's calibration, --underlay's image.
struct CameraFiles {
  std::optional<camera::CameraInfo> info;        // none without --camera-info
  std::shared_ptr<const image::Image> underlay;  // null without --underlay
};

// Reads the files `request` names with --camera-info and --underlay (none when it names no camera).
// Throws urdfsnap::Error for an unreadable or bad file (located in it).
CameraFiles ReadCameraFiles(const RenderRequest& request);

// The camera `request` asks for, or nullopt when it names none (no --camera-info, --camera-frame
// or --camera-pose; a calibration in `files.info` counts as --camera-info). Without --camera-info the camera has square pixels, the principal point at
// the centre and `settings.view`'s field of view at `settings.size`; with it, `settings.size`
// becomes the calibration's. `files` must be ReadCameraFiles of a request naming the same files;
// reads no file. Throws urdfsnap::Error naming the option through `label` for a bad value, a
// camera option without a camera, --distort without --camera-info, or --fit with a camera.
std::optional<render::CameraSettings> ParseCameraSettings(const RenderRequest& request, const CameraFiles& files,
                                                          const OptionLabel& label, render::RenderSettings& settings);

}  // namespace urdfsnap::request
