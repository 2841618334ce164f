// `urdfsnap render`: MODEL + joint values + view → PNG, written atomically. The view and display
// options come from request::TextOptions/FlagOptions, the table snapshot suites read as well.
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "cli/model_source.h"
#include "image/png_writer.h"
#include "gl/gl_context.h"
#include "request/render_session.h"

namespace urdfsnap::cli {

namespace {

struct RenderOptions {
  ModelSource model;
  std::string output;
  std::vector<std::string> joint_words;  // NAME=VALUE
  request::RenderRequest request;        // everything else, filled by CLI11 directly
};

std::string DefaultOutput(const std::string& model_path) {
  std::filesystem::path stem = std::filesystem::path(model_path).stem();
  if (stem.extension() == ".urdf") stem = stem.stem();   // robot.urdf.xacro → robot
  return (std::filesystem::path("output") / stem).string() + ".png";
}

void Run(RenderOptions& o) {
  const auto gl_loading = gl::StartLoadingGl();  // overlaps loading Mesa with reading the model
  o.request.model = o.model.ToRequest();
  for (const auto& word : o.joint_words) model::ParseJointAssignment(word, o.request.joints);
  Warnings warnings;
  request::RenderSession session;
  image::Image frame;
  try {
    frame = session.Render(
        o.request, [](std::string_view name) { return "--" + std::string(name); }, warnings);
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarnings(warnings);
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
  cmd->add_option("--joints", o->request.joint_file,
                  "YAML/JSON joint file: {name: value} or {name: [...], position: [...]}");
  for (const request::TextOption& option : request::TextOptions()) {
    cmd->add_option("--" + std::string(option.name), o->request.*option.field, option.help);
  }
  for (const request::FlagOption& option : request::FlagOptions()) {
    cmd->add_flag("--" + std::string(option.name), o->request.*option.field, option.help);
  }
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
