// The live view's one seam to the render core (request::RenderSession): a RenderRequest rendered
// to PNG bytes, the model loaded afresh with the list of files it read (to watch them), and the
// view a request renders with. Everything the server knows about rendering goes through here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "gl/backend.h"
#include "model/robot.h"
#include "render/render_settings.h"
#include "request/render_request.h"

namespace urdfsnap::request {
class RenderSession;
}

namespace urdfsnap::serve {

// A robot loaded for the live view, with every file its loading and first render read.
struct WatchedModel {
  std::shared_ptr<const model::Robot> robot;
  std::vector<std::string> warnings;  // the model's and its first render's
  std::vector<std::string> files;     // model file, xacro includes, YAML, meshes, textures
};

// Renders frames one at a time; not thread-safe (the server lets one thread render at a time).
class FrameSource {
 public:
  // backend: the GL backend of the session's contexts ({}: URDFSNAP_GL_BACKEND, else auto).
  explicit FrameSource(const gl::BackendChoice& backend = {});
  ~FrameSource();
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  // The PNG file `urdfsnap render` writes for `request`, byte for byte. Option errors name the
  // option as render's command line does ("--yaw 'x': ..."). Throws urdfsnap::Error.
  std::string RenderPng(const request::RenderRequest& request, Warnings& warnings);

  // Forgets every loaded model, loads `request`'s model from its files and renders `request`
  // once (so every mesh and texture it shows is read and checked). Throws urdfsnap::Error as
  // `urdfsnap render` would for the same request.
  WatchedModel Reload(const request::RenderRequest& request);

  // The settings `request` renders with, its view as the render frames it (--fit applied).
  // Throws urdfsnap::Error.
  render::RenderSettings ResolvedSettings(const request::RenderRequest& request, Warnings& warnings);

 private:
  std::unique_ptr<request::RenderSession> session_;
};

}  // namespace urdfsnap::serve
