// The typed settings of one render, parsed once from text (command line, suite file, `.rviz`) by
// the request stage, or filled in by C++ users directly: what the displays show, the orbit view,
// the image size, multisampling and view fitting, or a calibrated camera. Defaults are RViz's.
#pragma once

#include <optional>

#include "render/camera_settings.h"
#include "scene/orbit_view.h"
#include "scene/scene_options.h"

namespace urdfsnap::render {

struct ImageSize {
  int width = 640;    // pixels, 1 to image::kMaxImageSide
  int height = 480;
};

// --fit: how the view is framed around the robot.
enum class Fit {
  kNone,          // the orbit view as given
  kFit,           // focal point at the centre of the robot's bounds, distance to frame it all
  kKeepFocal,     // the given focal point, distance to frame it all
};

struct RenderSettings {
  scene::SceneOptions scene;   // displays, fixed frame, background, where files are found
  scene::OrbitView view;       // the camera
  // the frame whose origin the view's focal point is relative to (RViz's Target Frame); "" for the
  // fixed frame
  std::string target_frame;
  ImageSize size;
  int samples = 4;             // multisampling per pixel, 4 as RViz requests; 0 = off
  Fit fit = Fit::kNone;
  std::optional<CameraSettings> camera;   // when set, seen through it instead of `view`, at its size
};

}  // namespace urdfsnap::render
