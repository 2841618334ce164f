// RenderSession: option values checked and applied on top of RViz's defaults and the .rviz file,
// joint values resolved, the scene built and drawn.
#include "request/render_session.h"

#include <numbers>

#include "common/error.h"
#include "model/forward_kinematics.h"
#include "common/number_text.h"
#include "scene/mesh_prefetch.h"
#include "render/rviz_config.h"
#include "scene/scene_builder.h"
#include "scene/view_fitting.h"
#include "request/value_parsing.h"

namespace urdfsnap::request {

namespace {

double ParseInRange(const std::string& text, const std::string& option, double low, double high) {
  const double value = ParseFinite(text, option);
  if (value < low || value > high) {
    throw Error(option + " '" + text + "': expected a value from " + FormatNumber(low) +
                " to " + FormatNumber(high));
  }
  return value;
}

Eigen::Vector3f ParseColour(const std::string& text, const std::string& option) {
  const Eigen::Vector3d rgb = ParseVector3(text, option);
  if (rgb.minCoeff() < 0 || rgb.maxCoeff() > 255) {
    throw Error(option + " '" + text + "': expected R,G,B from 0 to 255");
  }
  return (rgb / 255).cast<float>();
}

void ApplyView(const RenderRequest& r, const OptionLabel& label, scene::OrbitView& view) {
  if (!r.yaw.empty()) view.yaw = ParseFinite(r.yaw, label("yaw"));
  if (!r.pitch.empty()) view.pitch = ParseFinite(r.pitch, label("pitch"));
  if (!r.distance.empty()) view.distance = ParseInRange(r.distance, label("distance"), 0.01, 1e6);
  if (!r.focal.empty()) view.focal = ParseVector3(r.focal, label("focal"));
  // RViz's Field of View property range, 0.001 to π/2 rad (orbit_view_controller.cpp L81-85)
  if (!r.fov.empty()) view.fov_y = ParseInRange(r.fov, label("fov"), 0.06, 90) * std::numbers::pi / 180;
}

void ApplyScene(const RenderRequest& r, const OptionLabel& label, scene::SceneOptions& scene) {
  if (!r.fixed_frame.empty()) scene.fixed_frame = r.fixed_frame;
  if (!r.background.empty()) scene.background = ParseColour(r.background, label("background"));
  if (!r.alpha.empty()) scene.alpha = ParseInRange(r.alpha, label("alpha"), 0, 1);
  if (r.collision) scene.show_collision = true;
  if (r.no_visual) scene.show_visual = false;
  if (r.no_grid) scene.grid.enabled = false;
  if (r.tf) scene.tf.enabled = true;
  if (r.no_tf_names) scene.tf.show_names = false;
  if (r.no_tf_axes) scene.tf.show_axes = false;
  if (r.no_tf_arrows) scene.tf.show_arrows = false;
  if (!r.tf_scale.empty()) scene.tf.marker_scale = ParseInRange(r.tf_scale, label("tf-scale"), 0, 1e6);
  scene.allow_missing_meshes = r.allow_missing_meshes;
}

void AddAll(const Warnings& from, Warnings& to) {
  for (const auto& message : from.messages()) to.Add(message);
}

}  // namespace

RenderSession::RenderSession() = default;
RenderSession::~RenderSession() = default;

const RenderSession::LoadedModel& RenderSession::Model(const ModelRequest& request) {
  auto found = models_.find(request);
  if (found != models_.end()) return found->second;
  Warnings warnings;
  model::Robot robot = LoadModel(request, warnings);
  return models_.emplace(request, LoadedModel{std::move(robot), std::move(warnings)}).first->second;
}

gl::Renderer& RenderSession::RendererFor(int samples) {
  std::unique_ptr<gl::Renderer>& renderer = renderers_[samples];
  if (!renderer) renderer = std::make_unique<gl::Renderer>(samples);
  return *renderer;
}

image::Image RenderSession::Render(const RenderRequest& r, const OptionLabel& label,
                                   Warnings& warnings) {
  const ImageSize size = ParseImageSize(r.size, label("size"));
  render::RvizConfig config;
  if (!r.rviz.empty()) config = render::ReadRvizConfig(r.rviz, config, warnings);
  ApplyView(r, label, config.view);
  ApplyScene(r, label, config.scene);
  const LoadedModel& loaded = Model(r.model);
  const model::Robot& robot = loaded.robot;
  AddAll(loaded.warnings, warnings);
  config.scene.model_file = r.model.path;
  config.scene.packages = r.model.packages;
  // .rviz files often name a frame outside the robot (map, odom); RViz would show nothing useful
  if (r.fixed_frame.empty() && !config.scene.fixed_frame.empty() &&
      robot.FindLink(config.scene.fixed_frame) < 0) {
    warnings.Add(r.rviz + ": Fixed Frame '" + config.scene.fixed_frame +
                 "' is not a link of the robot; using the root link '" + robot.links()[0].name + "'");
    config.scene.fixed_frame.clear();
  }

  model::NamedValues given;
  if (!r.joint_file.empty()) given = model::ReadJointFile(r.joint_file);
  given.insert(given.end(), r.joints.begin(), r.joints.end());
  const std::vector<double> positions =
      model::ResolveJointPositions(robot, given, !r.no_clamp, warnings);
  scene::PrefetchMeshFiles(robot, config.scene);  // all cores on the first render of a model
  const scene::Scene scene =
      scene::BuildScene(robot, model::ComputeLinkPoses(robot, positions), config.scene, warnings);
  const double aspect = static_cast<double>(size.width) / size.height;
  if (r.fit) config.view = scene::FitView(scene, config.view, aspect, !r.focal.empty());
  return RendererFor(r.no_aa ? 0 : 4).Render(scene, config.view, size.width, size.height);
}

}  // namespace urdfsnap::request
