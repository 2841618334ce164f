// `urdfsnap render`: MODEL + joint values + view → PNG, written atomically. What the picture shows
// starts from RViz's defaults, then an optional .rviz file, then the command-line options.
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>

#include "cli/command.h"
#include "cli/model_source.h"
#include "cli/value_parsing.h"
#include "common/error.h"
#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"
#include "render/gl_context.h"
#include "render/renderer.h"
#include "render/rviz_config.h"
#include "render/scene_builder.h"
#include "render/view_fitting.h"

namespace urdfsnap::cli {

namespace {

// Options as typed; an empty string or unset optional means "not given, keep what is there".
struct RenderOptions {
  ModelSource model;
  std::string output;
  std::vector<std::string> joint_words;   // NAME=VALUE
  std::string joint_file;
  bool no_clamp = false;
  std::string size = "640x480";
  std::string rviz;
  std::string yaw, pitch, distance, focal, fov;
  bool fit = false;
  std::string fixed_frame;
  std::string background;
  std::string alpha;
  bool collision = false, no_visual = false, no_grid = false, no_aa = false;
  bool tf = false, no_tf_names = false, no_tf_axes = false, no_tf_arrows = false;
  bool allow_missing_meshes = false;
  std::string tf_scale;
};

std::string DefaultOutput(const std::string& model_path) {
  std::filesystem::path stem = std::filesystem::path(model_path).stem();
  if (stem.extension() == ".urdf") stem = stem.stem();   // robot.urdf.xacro → robot
  return (std::filesystem::path("output") / stem).string() + ".png";
}

double ParseInRange(const std::string& text, const std::string& option, double low, double high) {
  const double value = ParseFinite(text, option);
  if (value < low || value > high) {
    throw Error(option + " '" + text + "': expected a value from " + std::to_string(low) + " to " +
                std::to_string(high));
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

void ApplyView(const RenderOptions& o, render::OrbitView& view) {
  if (!o.yaw.empty()) view.yaw = ParseFinite(o.yaw, "--yaw");
  if (!o.pitch.empty()) view.pitch = ParseFinite(o.pitch, "--pitch");
  if (!o.distance.empty()) view.distance = ParseInRange(o.distance, "--distance", 0.01, 1e6);
  if (!o.focal.empty()) view.focal = ParseVector3(o.focal, "--focal");
  // RViz's Field of View property range, 0.001 to π/2 rad (orbit_view_controller.cpp L81-85)
  if (!o.fov.empty()) view.fov_y = ParseInRange(o.fov, "--fov", 0.06, 90) * std::numbers::pi / 180;
}

void ApplyScene(const RenderOptions& o, render::SceneOptions& scene) {
  if (!o.fixed_frame.empty()) scene.fixed_frame = o.fixed_frame;
  if (!o.background.empty()) scene.background = ParseColour(o.background, "--background");
  if (!o.alpha.empty()) scene.alpha = ParseInRange(o.alpha, "--alpha", 0, 1);
  if (o.collision) scene.show_collision = true;
  if (o.no_visual) scene.show_visual = false;
  if (o.no_grid) scene.grid.enabled = false;
  if (o.tf) scene.tf.enabled = true;
  if (o.no_tf_names) scene.tf.show_names = false;
  if (o.no_tf_axes) scene.tf.show_axes = false;
  if (o.no_tf_arrows) scene.tf.show_arrows = false;
  if (!o.tf_scale.empty()) scene.tf.marker_scale = ParseInRange(o.tf_scale, "--tf-scale", 0, 1e6);
}

void Run(const RenderOptions& o) {
  render::StartLoadingGl();  // overlaps loading Mesa with reading the model
  const ImageSize size = ParseImageSize(o.size, "--size");
  Warnings warnings;
  render::RvizConfig config;
  if (!o.rviz.empty()) config = render::ReadRvizConfig(o.rviz, config, warnings);
  ApplyView(o, config.view);
  ApplyScene(o, config.scene);
  const model::Robot robot = o.model.Load(warnings);
  config.scene.model_file = o.model.path;
  config.scene.packages = ParsePackageWords(o.model.packages);
  config.scene.allow_missing_meshes = o.allow_missing_meshes;
  // .rviz files often name a frame outside the robot (map, odom); RViz would show nothing useful
  if (o.fixed_frame.empty() && !config.scene.fixed_frame.empty() &&
      robot.FindLink(config.scene.fixed_frame) < 0) {
    warnings.Add(o.rviz + ": Fixed Frame '" + config.scene.fixed_frame +
                 "' is not a link of the robot; using the root link '" + robot.links()[0].name + "'");
    config.scene.fixed_frame.clear();
  }

  model::NamedValues given;
  if (!o.joint_file.empty()) given = model::ReadJointFile(o.joint_file);
  for (const auto& word : o.joint_words) model::ParseJointAssignment(word, given);
  const std::vector<double> positions = model::ResolveJointPositions(robot, given, !o.no_clamp, warnings);
  const render::Scene scene =
      render::BuildScene(robot, model::ComputeLinkPoses(robot, positions), config.scene, warnings);
  const double aspect = static_cast<double>(size.width) / size.height;
  if (o.fit) config.view = render::FitView(scene, config.view, aspect, !o.focal.empty());
  PrintWarnings(warnings);

  render::Renderer renderer(o.no_aa ? 0 : 4);
  const image::Image frame = renderer.Render(scene, config.view, size.width, size.height);
  const std::string output = o.output.empty() ? DefaultOutput(o.model.path) : o.output;
  if (o.output.empty()) std::filesystem::create_directories("output");
  image::WritePng(frame, output);
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a robot pose to a PNG image, as RViz shows it");
  o->model.AddOptions(*cmd);
  cmd->add_option("-o,--output", o->output, "PNG file to write (default output/<model>.png)");
  cmd->add_option("-j,--joint", o->joint_words, "joint value NAME=VALUE in rad or m (repeatable)");
  cmd->add_option("--joints", o->joint_file,
                  "YAML/JSON joint file: {name: value} or {name: [...], position: [...]}");
  cmd->add_flag("--no-clamp", o->no_clamp, "do not clamp values to the joint limits");
  cmd->add_option("--size", o->size, "image size WxH in pixels, up to 16384x16384")->capture_default_str();
  cmd->add_option("--rviz", o->rviz,
                  "an RViz .rviz config: background, fixed frame, Grid, RobotModel, TF and Orbit view "
                  "(the options below override it)");
  cmd->add_option("--yaw", o->yaw, "orbit yaw about +Z in rad (RViz default 0.785398)");
  cmd->add_option("--pitch", o->pitch, "orbit pitch in rad (RViz default 0.785398)");
  cmd->add_option("--distance", o->distance, "orbit distance in m (RViz default 10)");
  cmd->add_option("--focal", o->focal, "orbit focal point X,Y,Z in m (RViz default 0,0,0)");
  cmd->add_option("--fov", o->fov, "vertical field of view in degrees (RViz default 45)");
  cmd->add_flag("--fit", o->fit,
                "choose the distance (and, without --focal, the focal point) so the robot fills the image");
  cmd->add_option("--fixed-frame", o->fixed_frame,
                  "link whose frame the scene is shown in (default: the root link)");
  cmd->add_option("--background", o->background, "background colour R,G,B 0-255 (RViz default 48,48,48)");
  cmd->add_option("--alpha", o->alpha, "RobotModel alpha, 0 to 1 (RViz default 1)");
  cmd->add_flag("--collision", o->collision, "show collision geometry (RViz default off)");
  cmd->add_flag("--no-visual", o->no_visual, "hide visual geometry (RViz default shown)");
  cmd->add_flag("--no-grid", o->no_grid, "hide the grid (RViz default shown)");
  cmd->add_flag("--tf", o->tf, "show the TF display: frame names, axes and parent arrows (RViz default off)");
  cmd->add_flag("--no-tf-names", o->no_tf_names, "TF display without frame names (RViz default shown)");
  cmd->add_flag("--no-tf-axes", o->no_tf_axes, "TF display without axes (RViz default shown)");
  cmd->add_flag("--no-tf-arrows", o->no_tf_arrows, "TF display without parent arrows (RViz default shown)");
  cmd->add_option("--tf-scale", o->tf_scale, "TF marker scale (RViz default 1)");
  cmd->add_flag("--no-aa", o->no_aa, "no multisampling (RViz default 4x)");
  cmd->add_flag("--allow-missing-meshes", o->allow_missing_meshes,
                "draw the rest of the robot when a mesh file cannot be found (one warning each)");
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
