// RobotSession: keyword values checked into typed settings, the model loaded once, the robot
// prepared once per display setting, one GL renderer per multisampling mode and backend.
#include "python/robot_session.h"

#include <numbers>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::python {

namespace {

// The command line's checks (request/value_parsing.cpp), worded for keyword arguments.
double InRange(double value, const char* keyword, double low, double high) {
  if (!(value >= low && value <= high)) {
    throw Error(std::string(keyword) + "=" + FormatNumber(value) + ": expected a value from " + FormatNumber(low) +
                " to " + FormatNumber(high));
  }
  return value;
}

double Finite(double value, const char* keyword) {
  if (!std::isfinite(value)) throw Error(std::string(keyword) + "=" + FormatNumber(value) + ": expected a finite number");
  return value;
}

Eigen::Vector3d Triple(const std::vector<double>& values, const char* keyword) {
  if (values.size() != 3) {
    throw Error(std::string(keyword) + ": expected 3 numbers, got " + std::to_string(values.size()));
  }
  return {Finite(values[0], keyword), Finite(values[1], keyword), Finite(values[2], keyword)};
}

render::ImageSize Size(const std::vector<int>& size) {
  if (size.size() != 2) throw Error("size: expected (width, height), got " + std::to_string(size.size()) + " numbers");
  for (int side : size) {
    if (side < 1 || side > image::kMaxImageSide) {
      throw Error("size=(" + std::to_string(size[0]) + ", " + std::to_string(size[1]) +
                  "): each side must be between 1 and " + std::to_string(image::kMaxImageSide) + " pixels");
    }
  }
  return {size[0], size[1]};
}

}  // namespace

render::RenderSettings MakeSettings(const RenderOptions& o, const request::ModelRequest& model) {
  render::RenderSettings s;
  s.size = Size(o.size);
  s.view.yaw = Finite(o.yaw, "yaw");
  s.view.pitch = Finite(o.pitch, "pitch");
  s.view.distance = InRange(o.distance, "distance", 0.01, 1e6);
  s.view.focal = Triple(o.focal, "focal");
  // as --fov: RViz's Field of View property range (orbit_view_controller.cpp L81-85)
  s.view.fov_y = InRange(o.fov, "fov", 0.06, 90) * std::numbers::pi / 180;
  const Eigen::Vector3d background = Triple(o.background, "background");
  if (background.minCoeff() < 0 || background.maxCoeff() > 255) {
    throw Error("background: expected (R, G, B) from 0 to 255");
  }
  s.scene.background = (background / 255).cast<float>();   // as ParseColour rounds it
  s.scene.alpha = InRange(o.alpha, "alpha", 0, 1);
  s.scene.fixed_frame = o.fixed_frame;
  s.scene.show_visual = o.visual;
  s.scene.show_collision = o.collision;
  s.scene.grid.enabled = o.grid;
  s.scene.tf.enabled = o.tf;
  s.scene.allow_missing_meshes = o.allow_missing_meshes;
  s.scene.model_file = model.path;
  s.scene.packages = model.packages;
  s.samples = o.antialias ? 4 : 0;
  s.fit = o.fit ? render::Fit::kFit : render::Fit::kNone;
  return s;
}

std::optional<gl::Backend> BackendKeyword(const std::string& name) {
  const gl::Backend backend = gl::ParseBackend(name);
  if (backend == gl::Backend::kAuto) return std::nullopt;
  gl::CheckCompiledIn(backend);
  return backend;
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

gl::Renderer& RobotSession::GlFor(int samples, std::optional<gl::Backend> backend) {
  std::unique_ptr<gl::Renderer>& gl = gl_[{samples, backend}];
  if (!gl) gl = std::make_unique<gl::Renderer>(samples, gl::BackendChoice(backend));
  return *gl;
}

}  // namespace urdfsnap::python
