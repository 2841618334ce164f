// The live view's one seam to the render core: a RenderRequest rendered to PNG bytes, the files a
// model was read from (to watch them), and forgetting loaded models so that the next frame reads
// the files again. Everything the server knows about rendering goes through this file, so a
// change of the render core changes only frame_source.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "model/robot.h"
#include "request/render_request.h"

namespace urdfsnap::request {
class RenderSession;
}

namespace urdfsnap::serve {

// Renders frames one at a time; not thread-safe (the server lets one thread render at a time).
class FrameSource {
 public:
  FrameSource();
  ~FrameSource();
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  // The PNG file `urdfsnap render` writes for `request`, byte for byte. Option errors name the
  // option as render's command line does ("--yaw 'x': ..."). Throws urdfsnap::Error.
  std::string RenderPng(const request::RenderRequest& request, Warnings& warnings);

  // Drops every loaded model (and what was derived from it), so the next frame reads the files.
  void ForgetModels();

 private:
  std::unique_ptr<request::RenderSession> session_;
};

// A robot loaded for the live view, with every file its loading read.
struct WatchedModel {
  model::Robot robot;
  Warnings warnings;
  // The model file, xacro includes and YAML files, mesh files and textures (those that exist).
  std::vector<std::string> files;
};

// Loads the robot `request` names, listing the files it read. Throws urdfsnap::Error.
WatchedModel LoadWatchedModel(const request::ModelRequest& request);

}  // namespace urdfsnap::serve
