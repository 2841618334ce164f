// The page's starting values: RViz's defaults, then the .rviz file, then the options given.
#include "serve/initial_view.h"

#include <cmath>
#include <filesystem>
#include <numbers>

#include <nlohmann/json.hpp>

#include "common/number_text.h"
#include "render/rviz_config.h"
#include "request/value_parsing.h"

namespace urdfsnap::serve {

namespace {

std::string Absolute(const std::string& path) {
  return path.empty() ? path : std::filesystem::absolute(path).lexically_normal().string();
}

std::string VectorText(double x, double y, double z) {
  return FormatNumber(x) + "," + FormatNumber(y) + "," + FormatNumber(z);
}

// The text an option was given as, else `fallback` (the .rviz file's or RViz's value).
std::string Given(const std::string& given, const std::string& fallback) {
  return given.empty() ? fallback : given;
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

std::string InitialViewJson(const request::RenderRequest& base, Warnings& warnings) {
  render::RvizConfig config;
  if (!base.rviz.empty()) config = render::ReadRvizConfig(base.rviz, config, warnings);
  const scene::OrbitView& view = config.view;
  const scene::SceneOptions& scene = config.scene;
  const Eigen::Vector3f rgb = (scene.background * 255).array().round();
  nlohmann::json options = {
      {"size", base.size},
      {"yaw", Given(base.yaw, FormatNumber(view.yaw))},
      {"pitch", Given(base.pitch, FormatNumber(view.pitch))},
      {"distance", Given(base.distance, FormatNumber(view.distance))},
      {"focal", Given(base.focal, VectorText(view.focal.x(), view.focal.y(), view.focal.z()))},
      {"alpha", Given(base.alpha, FormatNumber(scene.alpha))},
      {"background", Given(base.background, VectorText(rgb.x(), rgb.y(), rgb.z()))},
      {"no-grid", base.no_grid || !scene.grid.enabled},
      {"tf", base.tf || scene.tf.enabled},
      {"collision", base.collision || scene.show_collision},
      {"no-visual", base.no_visual || !scene.show_visual}};
  const double fov = base.fov.empty() ? view.fov_y : request::ParseFinite(base.fov, "--fov") * std::numbers::pi / 180;
  model::NamedValues given;
  if (!base.joint_file.empty()) given = model::ReadJointFile(base.joint_file);
  given.insert(given.end(), base.joints.begin(), base.joints.end());
  nlohmann::json joints = nlohmann::json::object();
  for (const auto& [name, value] : given) joints[name] = value;
  const nlohmann::json result = {
      {"options", options}, {"fov", fov}, {"joints", joints}, {"case", CaseBase(base)}};
  return result.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace urdfsnap::serve
