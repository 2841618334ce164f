// `urdfsnap render`: MODEL + joint values + view → PNG, written atomically. The view and display
// options come from request::TextOptions/FlagOptions, the table snapshot suites read as well.
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "cli/gl_options.h"
#include "cli/model_source.h"
#include "cli/render_options.h"
#include "image/depth_label_files.h"
#include "image/png_writer.h"
#include "gl/gl_context.h"
#include "request/render_session.h"

namespace urdfsnap::cli {

namespace {

struct RenderCommandOptions {
  ModelSource model;
  std::string output;
  std::string depth, labels;  // optional depth and link-label image files
  RenderOptions render;
  GlOptions gl_options;
};

std::string DefaultOutput(const std::string& model_path) {
  std::filesystem::path stem = std::filesystem::path(model_path).stem();
  if (stem.extension() == ".urdf") stem = stem.stem();   // robot.urdf.xacro → robot
  return (std::filesystem::path("output") / stem).string() + ".png";
}

void Run(RenderCommandOptions& o) {
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);  // overlaps loading Mesa with reading the model
  o.render.request.model = o.model.ToRequest();
  o.render.ParseJointWords();
  if (!o.depth.empty()) image::CheckDepthPath(o.depth, "--depth");
  if (!o.labels.empty()) image::CheckLabelsPath(o.labels, "--labels");
  Warnings warnings;
  request::RenderSession session(backend);
  request::Rendered rendered;
  try {
    rendered = session.Render(o.render.request, request::CommandLineLabel, warnings,
                              {true, !o.depth.empty(), !o.labels.empty()});
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarnings(warnings);
  const std::string output = o.output.empty() ? DefaultOutput(o.model.path) : o.output;
  if (o.output.empty()) std::filesystem::create_directories("output");
  image::WritePng(rendered.frame.colour, output);
  if (!o.depth.empty()) image::WriteDepthFile(rendered.frame.depth, o.depth);
  if (!o.labels.empty()) image::WriteLabelFiles(rendered.frame.labels, rendered.robot->LinkNames(), o.labels);
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a robot pose to a PNG image, as RViz shows it");
  o->model.AddOptions(*cmd);
  cmd->add_option("-o,--output", o->output, "PNG file to write (default output/<model>.png)");
  cmd->add_option("--depth", o->depth,
                  "also write the robot's depth image from the same view: FILE.png (16-bit, mm along "
                  "the viewing axis, 0 off the robot, ROS's 16UC1) or FILE.npy (float32 m, NaN off "
                  "the robot, ROS's 32FC1); robot geometry only (default: none)");
  cmd->add_option("--labels", o->labels,
                  "also write the link-label image FILE.png (16-bit: 1 + the index of the link "
                  "nearest at each pixel, in `info`'s link order, 0 off the robot) and FILE.json "
                  "(value -> link name) (default: none)");
  o->render.AddOptions(*cmd);
  o->gl_options.AddOptions(*cmd);
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
