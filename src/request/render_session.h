// Renders RenderRequests one after another in one process: each distinct model is loaded once and
// all frames are drawn by the same Renderer (one GL context per multisampling mode), which is what
// makes a snapshot suite of many views cheap.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "common/warnings.h"
#include "image/image.h"
#include "model/robot.h"
#include "gl/renderer.h"
#include "request/render_request.h"

namespace urdfsnap::request {

// How error messages name option `name` ("yaw"): "--yaw" on the command line, "suite.yaml:12: yaw"
// for a suite case.
using OptionLabel = std::function<std::string(std::string_view name)>;

class RenderSession {
 public:
  RenderSession();
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Renders `request`: RViz's defaults, then the .rviz file, then the options given. Warnings
  // (the model's, clamped joints, ...) go to `warnings`. Throws urdfsnap::Error for a bad option
  // value (named through `label`), an unreadable model or joint file, an unknown joint, ...
  image::Image Render(const RenderRequest& request, const OptionLabel& label, Warnings& warnings);

 private:
  struct LoadedModel {
    model::Robot robot;
    Warnings warnings;  // given again to every render of the model
  };
  const LoadedModel& Model(const ModelRequest& request);
  gl::Renderer& RendererFor(int samples);

  std::map<ModelRequest, LoadedModel> models_;
  std::map<int, std::unique_ptr<gl::Renderer>> renderers_;
};

}  // namespace urdfsnap::request
