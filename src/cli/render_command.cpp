// `urdfsnap render`: MODEL + joint values + view → PNG, written atomically. The view and display
// options come from request::TextOptions/FlagOptions, the table snapshot suites read as well.
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "cli/gl_options.h"
#include "cli/model_source.h"
#include "cli/render_options.h"
#include "camera/robot_mask.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/file_extension.h"
#include "dataset/rendered_keypoints.h"
#include "image/png_writer.h"
#include "render/frame_files.h"
#include "gl/gl_context.h"
#include "request/render_session.h"

namespace urdfsnap::cli {

namespace {

struct RenderCommandOptions {
  ModelSource model;
  std::string output;
  std::string depth, labels;  // optional depth and link-label image files
  std::string mask, keypoints;  // optional robot mask and keypoint files
  int mask_dilate = 0;
  RenderOptions render;
  GlOptions gl_options;
};

std::string DefaultOutput(const std::string& model_path) {
  std::filesystem::path stem = std::filesystem::path(model_path).stem();
  if (stem.extension() == ".urdf") stem = stem.stem();   // robot.urdf.xacro → robot
  return (std::filesystem::path("output") / stem).string() + ".png";
}

void CheckExtension(const std::string& path, const std::string& extension, const std::string& option) {
  if (LowerCaseExtension(path) != extension) {
    throw Error(option + " '" + path + "': expected a " + extension + " file");
  }
}

void Run(RenderCommandOptions& o) {
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);  // overlaps loading Mesa with reading the model
  o.render.request.model = o.model.ToRequest();
  o.render.ParseJointWords();
  if (!o.depth.empty()) render::CheckDepthPath(o.depth, "--depth");
  if (!o.labels.empty()) render::CheckLabelsPath(o.labels, "--labels");
  if (!o.mask.empty()) CheckExtension(o.mask, ".png", "--mask");
  if (o.mask_dilate < 0 || o.mask_dilate > 1000) {
    throw Error("--mask-dilate " + std::to_string(o.mask_dilate) + ": expected a number of pixels from 0 to 1000");
  }
  if (!o.keypoints.empty()) CheckExtension(o.keypoints, ".json", "--keypoints");
  Warnings warnings;
  request::RenderSession session(backend);
  image::Frame frame;
  std::shared_ptr<const model::Robot> robot;
  std::string keypoints;
  try {
    const request::Prepared prepared = session.Prepare(
        o.render.request, [](std::string_view name) { return "--" + std::string(name); }, warnings);
    const bool wants_keypoints = !o.keypoints.empty();
    frame = session.Draw(prepared, {true, !o.depth.empty() || wants_keypoints,
                                    !o.labels.empty() || !o.mask.empty() || wants_keypoints});
    robot = session.LoadRobot(o.render.request.model, warnings);
    if (wants_keypoints) {
      const render::RenderSettings& s = prepared.settings;
      keypoints = dataset::RenderedKeypointsJson(
          *prepared.renderer, prepared.positions,
          s.camera ? *s.camera : render::OrbitCamera(s.view, s.size.width, s.size.height), frame);
    }
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarnings(warnings);
  const std::string output = o.output.empty() ? DefaultOutput(o.model.path) : o.output;
  if (o.output.empty()) std::filesystem::create_directories("output");
  image::WritePng(frame.colour, output);
  if (!o.depth.empty()) render::WriteDepthFile(frame.depth, o.depth);
  if (!o.labels.empty()) render::WriteLabelFiles(frame.labels, *robot, o.labels);
  if (!o.mask.empty()) image::WriteGray8Png(camera::RobotMask(frame.labels, o.mask_dilate), o.mask);
  if (!o.keypoints.empty()) WriteFileAtomically(o.keypoints, keypoints);
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
  cmd->add_option("--mask", o->mask,
                  "also write the robot's binary mask FILE.png (8-bit: 255 on the robot, 0 elsewhere), "
                  "as a robot self-filter uses it (default: none)");
  cmd->add_option("--mask-dilate", o->mask_dilate,
                  "grow the --mask by N pixels (a disc), 0 to 1000, for self-filtering depth near the "
                  "outline (default 0)");
  cmd->add_option("--keypoints", o->keypoints,
                  "also write FILE.json: every link frame's and joint origin's pixel (u, v) under the "
                  "camera (OpenCV's projectPoints convention, distortion included), depth, whether "
                  "it is in the image and visible, and the camera (K, D, pose) (default: none)");
  o->render.AddOptions(*cmd);
  o->gl_options.AddOptions(*cmd);
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
