// The live view's one seam to the render core (request::RenderSession): the server's request
// resolved once per (re)load — its model loaded, its .rviz and joint files read — and each query
// applied over that, rendered to PNG bytes, reading no file. Everything the server knows about
// rendering goes through here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "gl/backend.h"
#include "model/joint_values.h"
#include "model/robot.h"
#include "render/render_settings.h"
#include "request/render_request.h"
#include "request/resolved_request.h"
#include "scene/orbit_view.h"

namespace urdfsnap::request {
class RenderSession;
}

namespace urdfsnap::serve {

struct RecordingView;

// A robot loaded for the live view, with every file its loading and first render read.
struct WatchedModel {
  std::shared_ptr<const model::Robot> robot;
  std::vector<std::string> warnings;  // the model's and its first render's
  std::vector<std::string> files;     // model file, xacro includes, YAML, meshes, textures, .rviz, joint file
};

// Where the page starts: the settings the server's request renders with (the view fitted) and
// the joint values it gives.
struct StartingView {
  render::RenderSettings settings;
  model::NamedValues joints;
};

// Renders frames one at a time; not thread-safe (the server lets one thread render at a time).
class FrameSource {
 public:
  // backend: the GL backend of the session's contexts ({}: URDFSNAP_GL_BACKEND, else auto).
  explicit FrameSource(const gl::BackendChoice& backend = {});
  ~FrameSource();
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  // Forgets every loaded model, reads `base`'s .rviz and joint files, loads its model from its
  // files and renders `base` once (so every mesh and texture it shows is read and checked).
  // Throws urdfsnap::Error as `urdfsnap render` would for the same request.
  WatchedModel Reload(const request::RenderRequest& base);

  // The PNG file `urdfsnap render` writes for `request` (the base given to the last Reload with a
  // query's options applied: the same .rviz and joint files), byte for byte, reading no file.
  // Option errors name the option as render's command line does ("--yaw 'x': ..."). Throws
  // urdfsnap::Error.
  std::string RenderPng(const request::RenderRequest& request, Warnings& warnings);

  // The PNG of `request` at `at` seconds of the recording `recording` draws.
  std::string RenderMomentPng(const RecordingView& recording, const request::RenderRequest& request, double at,
                              Warnings& warnings);

  // The orbit view that frames the robot as `request` shows it (its pose, displays, size and view
  // direction, not its focal point): the view `render --fit` draws without --focal; or, for a
  // `link`, that link's geometry (the links below it when it has none of its own; for a frame
  // with nothing below it either, such as a tool point, the nearest link above it with some), the
  // focal point at its centre. Throws urdfsnap::Error for an option, an unknown link or a robot
  // with nothing shown to frame.
  scene::OrbitView FitView(const request::RenderRequest& request, const std::string& link, Warnings& warnings);

  // Where the page starts for the base of the last Reload. Throws urdfsnap::Error.
  StartingView Start(Warnings& warnings);

 private:
  std::unique_ptr<request::RenderSession> session_;
  request::RenderRequest base_;      // of the last Reload
  request::RequestFiles base_files_;  // its .rviz and joint files, read by the last Reload
};

}  // namespace urdfsnap::serve
