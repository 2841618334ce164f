// RobotSession: keyword values parsed into typed settings by the request stage, the model loaded
// once, the robot prepared once per display setting, one GL renderer per multisampling mode and backend.
#include "python/robot_session.h"

#include <algorithm>

#include "common/error.h"
#include "request/settings_parsing.h"

namespace urdfsnap::python {

std::optional<gl::Backend> BackendKeyword(const std::string& name) {
  const gl::Backend backend = gl::ParseBackend(name);
  if (backend == gl::Backend::kAuto) return std::nullopt;
  gl::CheckCompiledIn(backend);
  return backend;
}

render::RenderSettings RobotSession::Settings(const RenderCall& call, Warnings& warnings) const {
  request::RenderRequest request = call.request;
  request.model = model_;
  // the keyword's name: tf_scale for --tf-scale
  const request::OptionLabel keyword = [](std::string_view option) {
    std::string name(option);
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
  };
  render::RenderSettings settings = request::ParseRenderSettings(request, keyword, warnings);
  if (call.underlay) {
    if (!settings.camera) throw Error("underlay needs a camera: camera_info, camera_frame or camera_pose");
    settings.camera->underlay = std::make_shared<const image::Image>(*call.underlay);
    settings.camera->underlay_file = "underlay";
  }
  return settings;
}

RobotSession::RobotSession(request::ModelRequest model)
    : model_(std::move(model)), robot_(request::LoadModel(model_, load_warnings_).robot),
      movable_joints_(robot_->MovableJointNames()) {}

std::vector<double> RobotSession::Positions(const model::NamedValues& given, bool clamp, Warnings& warnings) const {
  return model::ResolveJointPositions(*robot_, given, clamp, warnings);
}

const render::RobotRenderer& RobotSession::RendererFor(const scene::SceneOptions& options, Warnings& warnings) {
  if (!prepared_ || *prepared_options_ != options) {
    prepared_.reset();   // the old robot's meshes go before the new one's are loaded
    prepared_warnings_.Clear();
    prepared_ = std::make_unique<render::RobotRenderer>(robot_, options, prepared_warnings_);
    prepared_options_ = options;
  }
  for (const std::string& message : prepared_warnings_.messages()) warnings.Add(message);
  return *prepared_;
}

gl::SceneRenderer& RobotSession::GlFor(int samples, std::optional<gl::Backend> backend) {
  std::unique_ptr<gl::SceneRenderer>& gl = gl_[{samples, backend}];
  if (!gl) gl = std::make_unique<gl::SceneRenderer>(samples, gl::BackendChoice(backend));
  return *gl;
}

}  // namespace urdfsnap::python
