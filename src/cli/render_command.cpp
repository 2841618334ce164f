// `urdfsnap render`: MODEL + joint values + view → PNG, written atomically. The view and display
// options come from request::TextOptions/FlagOptions, the table snapshot suites read as well.
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

#include "cli/bag_model.h"
#include "cli/bag_still.h"
#include "cli/command.h"
#include "cli/display_options.h"
#include "cli/gl_options.h"
#include "cli/ignored_options.h"
#include "cli/model_source.h"
#include "cli/render_options.h"
#include "common/error.h"
#include "common/file_extension.h"
#include "common/output_plan.h"
#include "dataset/frame_extras.h"
#include "image/depth_label_files.h"
#include "image/image_file_names.h"
#include "image/png_writer.h"
#include "motion/trajectory_file.h"
#include "gl/gl_context.h"
#include "request/display_frame.h"
#include "request/render_session.h"
#include "request/request_inputs.h"

namespace urdfsnap::cli {

namespace {

struct RenderCommandOptions {
  ModelSource model;
  std::string output;
  std::string depth, labels;  // optional depth and link-label image files
  std::string mask, keypoints;  // optional robot mask and keypoint files
  int mask_dilate = 0;
  RenderOptions render;
  DisplayOptions displays;
  BagStillOptions bag;   // --bag, --at: a moment of a recording
  GlOptions gl_options;
};

std::string DefaultOutput(const std::string& model_path) {
  std::filesystem::path stem = std::filesystem::path(model_path).stem();
  if (stem.extension() == ".urdf") stem = stem.stem();   // robot.urdf.xacro → robot
  return (std::filesystem::path("output") / stem).string() + ".png";
}

void CheckJsonExtension(const std::string& path, const std::string& option) {
  if (LowerCaseExtension(path) != ".json") throw Error(option + " '" + path + "': expected a .json file");
}

void Run(RenderCommandOptions& o) {
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);  // overlaps loading Mesa with reading the model
  // a recording: MODEL may be the bag itself, and without a MODEL the bag's robot description
  if (o.bag.bag.empty() && !o.model.path.empty() && motion::IsBag(o.model.path)) o.bag.bag = std::exchange(o.model.path, "");
  if (o.bag.bag.empty() && !o.bag.at.empty()) throw Error("--at: a moment of a recording; give the recording with --bag");
  o.bag.camera.RequireBag(!o.bag.bag.empty(), "give the recording with --bag");
  if (o.bag.bag.empty() && o.model.path.empty()) throw Error("render: give MODEL (a URDF or xacro file) or --bag");
  std::optional<BagModel> bag_model;
  if (o.model.path.empty()) bag_model.emplace(o.bag.bag, o.bag.description_topic);
  o.render.request.model = o.model.ToRequest();
  if (bag_model) o.render.request.model.path = bag_model->path();
  o.render.ParseJointWords();
  const std::string output = o.output.empty() ? DefaultOutput(bag_model ? o.bag.bag : o.model.path) : o.output;
  dataset::CheckMaskDilate(o.mask_dilate, "--mask-dilate");
  // every output checked, and its folder made, before drawing; all written, or none
  OutputPlan plan;
  request::AddRequestInputs(plan, o.render.request);
  if (!o.bag.bag.empty()) plan.AddInput(o.bag.bag, "--bag");
  // (the default output/ folder is made; a folder given must exist)
  plan.AddFile(output, o.output.empty() ? "the output" : "-o", o.output.empty());
  if (!o.depth.empty()) plan.AddFile(o.depth, "--depth", false);
  if (!o.labels.empty()) {
    plan.AddFile(o.labels, "--labels", false);
    plan.AddFile(image::LabelNamesFile(o.labels), "the link names of --labels", false);
  }
  if (!o.mask.empty()) plan.AddFile(o.mask, "--mask", false);
  if (!o.keypoints.empty()) plan.AddFile(o.keypoints, "--keypoints", false);
  plan.Prepare();
  // the extensions after the plan's checks, whose errors say more (a folder, the model itself, one
  // output twice); Prepare made no folder for these (only the default output/, always .png)
  image::CheckImageFileName(output, image::ImageKind::kColour, "-o");
  if (!o.depth.empty()) image::CheckImageFileName(o.depth, image::ImageKind::kDepth, "--depth");
  if (!o.labels.empty()) image::CheckImageFileName(o.labels, image::ImageKind::kLabels, "--labels");
  if (!o.mask.empty()) image::CheckImageFileName(o.mask, image::ImageKind::kMask, "--mask");
  if (!o.keypoints.empty()) CheckJsonExtension(o.keypoints, "--keypoints");
  Warnings warnings;
  WarnOfUnusedBagTopics(o.bag.topic, o.bag.description_topic, !o.bag.bag.empty(), bag_model.has_value(), "--bag",
                        warnings);
  WarnOfUnusedMaskDilate(o.mask_dilate, o.mask, warnings);
  request::RenderSession session(backend);
  image::Frame frame;
  std::shared_ptr<const model::Robot> robot;
  const dataset::ExtrasWanted wanted{!o.mask.empty(), o.mask_dilate, !o.keypoints.empty()};
  dataset::FrameExtras extras;
  try {
    std::optional<BagStill> still;
    if (!o.bag.bag.empty()) {
      still.emplace(o.bag, session, o.render.request, bag_model.has_value(), o.displays, warnings);
    }
    const request::Prepared prepared =
        still ? still->prepared() : session.Prepare(o.render.request, request::CommandLineLabel, warnings);
    const image::FrameOutputs outputs = dataset::OutputsFor({true, !o.depth.empty(), !o.labels.empty()}, wanted);
    if (still) {
      frame = still->Draw(session, outputs, warnings);   // with the recording's displays at the moment
    } else if (o.displays.empty() && prepared.settings.displays.empty()) {
      frame = session.Draw(prepared, outputs);
    } else {
      const scene::SceneOptions& scene = prepared.settings.scene;
      const display::DisplaySet displays = o.displays.MakeDisplays(
          prepared.settings.displays, scene.fixed_frame, request::MarkerResourcesFor(scene), warnings);
      frame = request::DrawWithDisplays(session, prepared, displays, warnings, outputs);
    }
    robot = prepared.robot;
    const render::RenderSettings& s = prepared.settings;
    extras = dataset::MakeFrameExtras(wanted, *prepared.renderer, prepared.positions,
                                      s.camera ? *s.camera : render::OrbitCamera(s.view, s.size.width, s.size.height),
                                      frame);
  } catch (const Error& e) {
    PrintWarningsBeforeError(warnings);
    if (bag_model) throw Error(bag_model->Located(e.what()));
    throw;
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarnings(warnings);
  plan.Write(output, image::EncodePng(frame.colour));
  if (!o.depth.empty()) {
    plan.Write(o.depth, image::EncodeDepthFile(frame.depth, o.depth));
  }
  if (!o.labels.empty()) {
    plan.Write(o.labels, image::EncodeLabels(frame.labels));
    plan.Write(image::LabelNamesFile(o.labels), image::LabelNamesJson(robot->LinkNames()));
  }
  if (!o.mask.empty()) plan.Write(o.mask, image::EncodeGray8Png(extras.mask));
  if (!o.keypoints.empty()) plan.Write(o.keypoints, extras.keypoints);
  plan.Commit();
}

}  // namespace

void AddRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a robot pose to a PNG image, as RViz shows it");
  o->model.AddOptions(*cmd, true);
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
  o->displays.AddOptions(*cmd);
  o->bag.AddOptions(*cmd);
  o->gl_options.AddOptions(*cmd);
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
