// The page's starting values, from the settings the server's request renders with.
#include "serve/initial_view.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/number_text.h"
#include "model/joint_values.h"

namespace urdfsnap::serve {

namespace {

std::string Absolute(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

std::string VectorText(double x, double y, double z) {
  return FormatNumber(x) + "," + FormatNumber(y) + "," + FormatNumber(z);
}

// The options and model a suite case needs to render as the server does.
nlohmann::json CaseBase(const request::RenderRequest& base) {
  nlohmann::json options = nlohmann::json::object();
  for (const auto& option : request::TextOptions()) {
    const std::string& value = base.*option.field;
    if (!value.empty()) options[option.name] = option.is_path ? Absolute(value) : value;
  }
  for (const auto& option : request::FlagOptions()) {
    if (base.*option.field) options[option.name] = true;
  }
  nlohmann::json args = nlohmann::json::object();
  for (const auto& [name, value] : base.model.xacro_args) args[name] = value;
  nlohmann::json packages = nlohmann::json::object();
  for (const auto& [name, dir] : base.model.packages) packages[name] = Absolute(dir);
  return {{"model", Absolute(base.model.path)},
          {"args", args},
          {"packages", packages},
          {"xacro-ns", base.model.xacro_ns},
          {"options", options}};
}

}  // namespace

std::string InitialViewJson(const request::RenderRequest& base, const render::RenderSettings& settings) {
  const scene::OrbitView& view = settings.view;
  const scene::SceneOptions& scene = settings.scene;
  const Eigen::Vector3f rgb = (scene.background * 255).array().round();
  // numbers in their shortest round-trip form, so that the page's first frame is the server's
  const nlohmann::json options = {
      {"size", std::to_string(settings.size.width) + "x" + std::to_string(settings.size.height)},
      {"yaw", FormatNumber(view.yaw)},
      {"pitch", FormatNumber(view.pitch)},
      {"distance", FormatNumber(view.distance)},
      {"focal", VectorText(view.focal.x(), view.focal.y(), view.focal.z())},
      {"alpha", FormatNumber(scene.alpha)},
      {"background", VectorText(rgb.x(), rgb.y(), rgb.z())},
      {"fit", false},  // the view above is fitted already
      {"no-grid", !scene.grid.enabled},
      {"tf", scene.tf.enabled},
      {"collision", scene.show_collision},
      {"no-visual", !scene.show_visual}};
  model::NamedValues given;
  if (!base.joint_file.empty()) given = model::ReadJointFile(base.joint_file);
  given.insert(given.end(), base.joints.begin(), base.joints.end());
  nlohmann::json joints = nlohmann::json::object();
  for (const auto& [name, value] : given) joints[name] = value;
  // the page's frame follows the window's size unless a size other than the default was asked for
  const bool size_given = base.size != request::RenderRequest{}.size;
  const nlohmann::json result = {{"options", options},     {"size_given", size_given}, {"fov", view.fov_y},
                                 {"joints", joints},       {"case", CaseBase(base)}};
  return result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace urdfsnap::serve
