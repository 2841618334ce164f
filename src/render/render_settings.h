// The typed settings of one render, parsed once from text (command line, suite file, `.rviz`) by
// the request stage, or filled in by C++ users directly: what the displays show, the orbit view,
// the image size, multisampling and view fitting, or a calibrated camera. Defaults are RViz's.
#pragma once

#include <optional>
#include <vector>

#include "display/display_settings.h"
#include "render/camera_settings.h"
#include "scene/orbit_view.h"
#include "scene/scene_options.h"
#include "scene/view_fitting.h"

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

// --fit-margin: the empty border --fit leaves on each side of the image, a fraction of the side's
// length or a number of pixels.
struct FitMargin {
  double amount = 0.05;
  bool pixels = false;

  // As fractions of the width and height of an image of `size`.
  scene::FitMargin For(ImageSize size) const {
    if (!pixels) return {amount, amount};
    return {amount / size.width, amount / size.height};
  }
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
  FitMargin fit_margin;
  std::optional<CameraSettings> camera;   // when set, seen through it instead of `view`, at its size
  // the message displays (Marker, Path, ...) of the .rviz file and --display, drawn from a bag's
  // or a message file's messages (display/display_set.h)
  std::vector<display::DisplaySettings> displays;
};

}  // namespace urdfsnap::render
