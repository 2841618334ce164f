// `urdfsnap render`: MODEL + joint values + view → PNG, written atomically.
#include <filesystem>
#include <memory>
#include <numbers>

#include "cli/command.h"
#include "cli/model_source.h"
#include "cli/value_parsing.h"
#include "common/error.h"
#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"
#include "render/renderer.h"
#include "render/scene_builder.h"

namespace urdfsnap::cli {

namespace {

struct RenderOptions {
  ModelSource model;
  std::string output;
  std::vector<std::string> joint_words;   // NAME=VALUE
  std::string joint_file;
  std::string size = "640x480";
  std::string yaw, pitch, distance, focal, fov;
  bool no_clamp = false;
  bool no_aa = false;
  bool no_grid = false;
  bool no_visual = false;
  bool collision = false;
  std::string fixed_frame;
  std::string alpha;
};

std::string DefaultOutput(const std::string& model_path) {
  std::filesystem::path stem = std::filesystem::path(model_path).stem();
  if (stem.extension() == ".urdf") stem = stem.stem();   // robot.urdf.xacro → robot
  return (std::filesystem::path("output") / stem).string() + ".png";
}

render::OrbitView ViewFrom(const RenderOptions& o) {
  render::OrbitView view;
  if (!o.yaw.empty()) view.yaw = ParseFinite(o.yaw, "--yaw");
  if (!o.pitch.empty()) view.pitch = ParseFinite(o.pitch, "--pitch");
  if (!o.distance.empty()) view.distance = ParseFinite(o.distance, "--distance");
  if (!o.focal.empty()) view.focal = ParseVector3(o.focal, "--focal");
  if (!o.fov.empty()) {
    const double degrees = ParseFinite(o.fov, "--fov");
    // RViz's Field Of View property range (orbit_view_controller.cpp L81-85)
    if (degrees < 0.06 || degrees > 90) throw Error("--fov '" + o.fov + "': expected 0.06 to 90 degrees");
    view.fov_y = degrees * std::numbers::pi / 180;
  }
  return view;
}

void Run(const RenderOptions& o) {
  const ImageSize size = ParseImageSize(o.size, "--size");
  const render::OrbitView view = ViewFrom(o);
  Warnings warnings;
  const model::Robot robot = o.model.Load(warnings);

  model::NamedValues given;
  if (!o.joint_file.empty()) given = model::ReadJointFile(o.joint_file);
  for (const auto& word : o.joint_words) model::ParseJointAssignment(word, given);
  const std::vector<double> positions = model::ResolveJointPositions(robot, given, !o.no_clamp, warnings);

  render::SceneOptions scene_options;
  scene_options.fixed_frame = o.fixed_frame;
  scene_options.show_visual = !o.no_visual;
  scene_options.show_collision = o.collision;
  scene_options.grid.enabled = !o.no_grid;
  if (!o.alpha.empty()) {
    scene_options.alpha = ParseFinite(o.alpha, "--alpha");
    if (scene_options.alpha < 0 || scene_options.alpha > 1) {
      throw Error("--alpha '" + o.alpha + "': expected a value from 0 to 1");
    }
  }
  const render::Scene scene =
      render::BuildScene(robot, model::ComputeLinkPoses(robot, positions), scene_options, warnings);
  PrintWarnings(warnings);

  render::Renderer renderer(o.no_aa ? 0 : 4);
  const image::Image frame = renderer.Render(scene, view, size.width, size.height);
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
  cmd->add_option("--size", o->size, "image size WxH in pixels")->capture_default_str();
  cmd->add_option("--yaw", o->yaw, "orbit yaw about +Z in rad (RViz default 0.785398)");
  cmd->add_option("--pitch", o->pitch, "orbit pitch in rad (RViz default 0.785398)");
  cmd->add_option("--distance", o->distance, "orbit distance in m (RViz default 10)");
  cmd->add_option("--focal", o->focal, "orbit focal point X,Y,Z in m (RViz default 0,0,0)");
  cmd->add_option("--fov", o->fov, "vertical field of view in degrees (RViz default 45)");
  cmd->add_option("--fixed-frame", o->fixed_frame, "link whose frame the scene is shown in (default: the root link)");
  cmd->add_option("--alpha", o->alpha, "RobotModel alpha, 0 to 1 (RViz default 1)");
  cmd->add_flag("--collision", o->collision, "show collision geometry (RViz default off)");
  cmd->add_flag("--no-visual", o->no_visual, "hide visual geometry (RViz default shown)");
  cmd->add_flag("--no-grid", o->no_grid, "hide the grid (RViz default shown)");
  cmd->add_flag("--no-aa", o->no_aa, "no multisampling (RViz default 4x)");
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
