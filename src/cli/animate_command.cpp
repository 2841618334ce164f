// `urdfsnap animate`: MODEL + a trajectory (CSV, ROS messages in YAML/JSON, a ROS 2 bag), or a
// bag alone as MODEL (its robot description and motion), and/or a turntable → MP4, WebM, GIF,
// animated WebP or a PNG sequence, with depth, label, mask and keypoint sequences from the same
// frames. Every output appears only when complete; --print-frame K instead prints the `render`
// options that make frame K.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <utility>

#include "animation/animation_frames.h"
#include "animation/frame_reproduction.h"
#include "animation/render_animation.h"
#include "animation/sequence_outputs.h"
#include "bag/joint_state_bag.h"
#include "bag/recorded_description.h"
#include "cli/bag_batch.h"
#include "cli/bag_camera_image.h"
#include "cli/bag_model.h"
#include "cli/bag_scene.h"
#include "cli/command.h"
#include "cli/display_options.h"
#include "cli/frame_memory.h"
#include "cli/gl_options.h"
#include "cli/ignored_options.h"
#include "cli/job_options.h"
#include "cli/model_source.h"
#include "cli/pieces_beside_workers.h"
#include "cli/render_options.h"
#include "cli/shard_options.h"
#include "cli/worker_processes.h"
#include "common/error.h"
#include "common/number_text.h"
#include "common/random_suffix.h"
#include "gl/gl_context.h"
#include "dataset/frame_extras.h"
#include "image/depth_label_files.h"
#include "gl/rasteriser_threads.h"
#include "motion/frame_plan.h"
#include "motion/frame_poses.h"
#include "motion/trajectory_file.h"
#include "request/render_session.h"
#include "request/request_inputs.h"
#include "request/value_parsing.h"
#include "shard/shard_assignment.h"
#include "shard/shard_spec.h"
#include "stream/progress_bar.h"
#include "video/frame_encoder.h"
#include "video/numbered_files.h"
#include "video/open_frame_encoder.h"

namespace urdfsnap::cli {

namespace {

// How long a turntable of a still pose lasts when --duration does not say.
constexpr double kStillTurntableSeconds = 6;

// The pieces a frame sequence is cut into per drawing process (dataset's samples, dearer, are cut into 4):
// a run of frames costs a line each way and its files opened, and the
// workers end within a piece of each other. With 4, one worker of a 121-frame Panda turntable sat
// idle for 0.2-0.5 s at the end while the other drew its last 15 frames.
constexpr int kFramePiecesPerWorker = 16;

struct AnimateOptions {
  ModelSource model;
  std::string output;
  std::string trajectory;
  std::string topic = bag::kDefaultJointStateTopic;
  std::string description_topic = bag::kDefaultDescriptionTopic;  // MODEL given as a bag
  std::string fps, speed, duration;  // checked as render checks its numbers; fps: the format's default
  std::string start, end;                   // the part of the trajectory played
  bool turntable = false;
  bool clamp = false, strict_joints = false;  // how the trajectory's joints meet the model's
  std::string depth, labels;  // optional depth and link-label sequences (patterns)
  std::string mask, keypoints;  // optional robot-mask and keypoint sequences (patterns)
  int mask_dilate = 0;
  std::string print_frame;    // a frame number: print its render options instead of writing
  bool quiet = false;
  bool model_from_bag = false;   // MODEL was a bag: its recorded description is the model
  ShardOptions sharding;      // a frame sequence's contiguous range of frames
  JobOptions jobs;            // worker processes drawing a frame sequence; a worker's pieces and suffix
  RenderOptions render;
  DisplayOptions displays;   // with the .rviz file's: message displays in every frame
  BagCameraOptions camera;   // a bag's camera image behind every frame, its calibration
  GlOptions gl_options;
};

std::optional<double> OptionalNumber(const std::string& text, const std::string& option) {
  if (text.empty()) return std::nullopt;
  return request::ParseFinite(text, option);
}

// The frames the options ask for. Throws Error for values PlanFrames/PlanStill refuse.
motion::FramePlan Plan(const AnimateOptions& o, const motion::Trajectory& trajectory) {
  const double fps = request::ParseFinite(o.fps, "--fps");
  const std::optional<double> speed = OptionalNumber(o.speed, "--speed");
  const std::optional<double> duration = OptionalNumber(o.duration, "--duration");
  const std::optional<double> start = OptionalNumber(o.start, "--start");
  const std::optional<double> end = OptionalNumber(o.end, "--end");
  if (o.trajectory.empty()) {
    if (start || end) throw Error("animate: --start and --end choose part of a trajectory; there is no --trajectory");
    if (!o.turntable) {
      throw Error("animate: nothing moves: give --trajectory FILE, --turntable or both");
    }
    if (speed) throw Error("animate: --speed plays a trajectory faster or slower; there is no --trajectory");
    return motion::PlanStill(duration.value_or(kStillTurntableSeconds), fps);
  }
  motion::TimeWindow window;
  if (start) window.start = motion::TrajectorySeconds(trajectory, *start, "--start");
  if (end) window.end = motion::TrajectorySeconds(trajectory, *end, "--end");
  return motion::PlanFrames(trajectory, fps, speed.value_or(1), duration, window);
}

// The frame number --print-frame names, within the animation.
std::int64_t FrameNumber(const std::string& text, const motion::FramePlan& plan) {
  double k = 0;
  if (!ParseNumber(text, k) || k != std::floor(k) || k < 0 || k >= static_cast<double>(plan.frame_count)) {
    throw Error("--print-frame '" + text + "': expected a frame number from 0 to " +
                std::to_string(plan.frame_count - 1) + " (the animation has " +
                std::to_string(plan.frame_count) + " frames)");
  }
  return static_cast<std::int64_t>(k);
}

// The shard this run takes. A video is one file of every frame and --print-frame renders nothing,
// so neither splits: an explicit --shard is then an error, the environment's shard is set aside.
shard::ShardChoice ChooseShard(const AnimateOptions& o) {
  if (!o.print_frame.empty()) {
    if (o.sharding.shard) throw Error("--shard: --print-frame prints one frame's options and renders nothing to split");
    return {};
  }
  const video::OutputFormat format = video::OutputFormatOf(o.output);
  if (format == video::OutputFormat::kPngSequence) return o.sharding.Choose();
  return o.sharding.Choose(o.output + " is one " + video::OutputFormatName(format) +
                           " file of every frame; only a frame sequence (such as -o frames/%05d.png) is split "
                           "over workers");
}

// "frames 25 to 49" of a shard's range, for its stderr line.
std::string RangeText(shard::FrameRange range) {
  if (range.size() == 0) return "no frames: fewer frames than shards";
  return "frames " + std::to_string(range.first) + " to " + std::to_string(range.end - 1);
}

// What the summary line says was written: "wrote run.mp4 (1.2 MB)", or for a sequence "wrote
// frames/%05d.png (frames 0 to 99)".
std::string WrittenText(const std::string& output, const shard::FrameRange& range) {
  if (video::OutputFormatOf(output) == video::OutputFormat::kPngSequence) {
    return "wrote " + output + " (" + RangeText(range) + ")";
  }
  std::error_code error;
  const auto bytes = std::filesystem::file_size(output, error);
  return "wrote " + output + (error ? "" : " (" + FormatBytes(bytes) + ")");
}

// Prints the warnings of `later` that `printed` does not hold already.
void PrintNewWarnings(const Warnings& printed, const Warnings& later) {
  Warnings fresh;
  for (const std::string& message : later.messages()) {
    const auto& old = printed.messages();
    if (std::find(old.begin(), old.end(), message) == old.end()) fresh.Add(message);
  }
  PrintWarnings(fresh);
}

// An animation ready to render: the robot prepared once, its frames planned and its camera fitted.
struct PreparedAnimation {
  BagScene scene;   // robot.settings.view before --fit (fitted over every frame by `frames`); TF only for a bag
  motion::Trajectory trajectory;
  motion::FramePlan plan;
  std::optional<motion::FramePoses> poses;
  std::optional<animation::AnimationFrames> frames;
  render::Fit fit = render::Fit::kNone;   // the request's --fit
};

// An OrbitView as one line of hexadecimal floating-point numbers, read back bit for bit.
std::string ViewLine(const scene::OrbitView& v) {
  std::string line;
  for (const double x : {v.yaw, v.pitch, v.distance, v.focal.x(), v.focal.y(), v.focal.z(), v.fov_y, v.near_clip, v.far_clip}) {
    char number[40];
    std::snprintf(number, sizeof number, "%a ", x);
    line += number;
  }
  return line;
}

scene::OrbitView ParseViewLine(const std::string& line) {
  scene::OrbitView v;
  const char* at = line.c_str();
  for (double* x : {&v.yaw, &v.pitch, &v.distance, &v.focal.x(), &v.focal.y(), &v.focal.z(), &v.fov_y, &v.near_clip, &v.far_clip}) {
    char* end = nullptr;
    *x = std::strtod(at, &end);
    if (end == at) throw Error("animate worker: expected its parent's fitted view, got '" + line + "'");
    at = end;
  }
  return v;
}

// Prepares the robot through `session` and plans and fits the frames (in place: `frames` keeps
// references to the plan and poses). A worker calls `while_parent_fits` with the robot and its
// poses ready, before it waits for its parent's camera.
void PrepareAnimation(const AnimateOptions& o, request::RenderSession& session, PreparedAnimation& a,
                      Warnings& warnings, const std::function<void(const PreparedAnimation&)>& while_parent_fits) {
  const request::RenderRequest& r = o.render.request;
  // a calibration from the bag (--camera-info-topic) is resolved once the first frame's moment is known
  std::optional<request::ResolvedRequest> resolved;
  if (o.camera.camera_info_topic.empty()) resolved = request::ResolveRequest(r, request::CommandLineLabel, warnings);
  if (!o.trajectory.empty()) a.trajectory = motion::ReadTrajectory(o.trajectory, {o.topic}, warnings);
  // a bag: the fixed frame through its TF (odom, map place the robot as RViz's Fixed Frame does),
  // and the TF display of its frames
  const bool bag = !o.trajectory.empty() && motion::IsBag(o.trajectory);
  o.camera.RequireBag(bag, "give a recording as MODEL or --trajectory");
  const double stamp_at_zero = a.trajectory.stamp_at_zero.value_or(0);
  a.plan = Plan(o, a.trajectory);
  if (!resolved) {
    resolved = ResolveWithBagCamera(r, o.camera, o.trajectory,
                                    std::llround((stamp_at_zero + a.plan.TrajectoryTime(0)) * 1e9), warnings);
  }
  // --fit frames every frame at once, below, not the first pose alone
  a.fit = std::exchange(resolved->settings.fit, render::Fit::kNone);
  render::Fit fit = a.fit;
  const model::NamedValues joints = resolved->joints;
  const bool clamp = resolved->clamp;
  PrepareBagScene(session, std::move(*resolved), bag ? o.trajectory : "", stamp_at_zero, o.model_from_bag, warnings,
                  a.scene);
  AddSceneDisplays(o.displays, bag ? o.trajectory : "", stamp_at_zero, a.scene, warnings);
  AddBagUnderlay(o.camera, r, o.trajectory, stamp_at_zero, a.scene);
  if (a.scene.underlay && !o.print_frame.empty()) {
    throw Error("--print-frame: the frames show the bag's camera images, which `render` draws with --bag " +
                o.trajectory + " --at SECONDS");
  }
  if (a.scene.displays && bag && !o.print_frame.empty()) {
    throw Error("--print-frame: the frames show the bag's messages, which `render` draws with --bag " + o.trajectory +
                " --at SECONDS");
  }
  // joints the trajectory does not name: the joint file, then -j, as render takes them
  const request::Prepared& robot = a.scene.robot;
  a.poses.emplace(*robot.robot, a.trajectory, joints, motion::JointRules{clamp, o.clamp, o.strict_joints}, warnings);
  if (a.scene.root && !o.print_frame.empty()) {
    throw Error("--print-frame: the frames are placed by TF in a fixed frame outside the robot, which `render` "
                "draws with --bag " + o.trajectory + " --at SECONDS");
  }
  const render::RenderSettings& settings = robot.settings;
  // a worker: the camera its parent fitted over every frame, not fitted again
  scene::OrbitView view = settings.view;
  if (o.jobs.worker() && fit != render::Fit::kNone) {
    while_parent_fits(a);
    const std::optional<std::string> line = ReadParentLine();
    if (!line) throw Error("animate worker: its parent ended before fitting the camera");
    view = ParseViewLine(*line);
    fit = render::Fit::kNone;
  }
  if (a.scene.camera_tf && !o.print_frame.empty()) {
    throw Error("--print-frame: the camera is placed by TF from '" + settings.camera->frame +
                "', which `render` draws with --bag " + o.trajectory + " --at SECONDS");
  }
  a.frames.emplace(*robot.renderer, a.plan, *a.poses,
                   animation::CameraRequest{view, settings.size, fit, settings.fit_margin, o.turntable, settings.camera,
                                            a.scene.camera_tf ? &*a.scene.camera_tf : nullptr},
                   warnings, a.scene.Additions());
}

// A worker's GL context made, its shaders compiled and the robot's meshes uploaded while its parent
// fits the camera: the first frame's pose drawn through the view before --fit, 16x16 pixels.
void WarmUpGl(request::RenderSession& session, const PreparedAnimation& a) {
  const request::Prepared& robot = a.scene.robot;
  Warnings repeated;   // the frames report the pose's warnings
  robot.renderer->Render(session.GlRenderer(robot.settings.samples), a.poses->At(a.plan.TrajectoryTime(0), repeated),
                         robot.settings.view, {16, 16}, {});
}

// --print-frame K: the render options that draw frame K, to stdout.
void PrintFrame(const AnimateOptions& o, const PreparedAnimation& a, Warnings& warnings) {
  const std::int64_t k = FrameNumber(o.print_frame, a.plan);
  const std::vector<double> positions = a.frames->Positions(k, warnings);
  scene::OrbitView view = a.frames->View(k);
  if (const animation::FollowedFrame* followed = a.frames->followed()) {
    // `render` with the same --follow adds the link's origin back for the frame's joints
    if (!followed->is_link()) {
      throw Error("--print-frame: the view follows a frame of the bag's TF, which `render` follows with --bag " +
                  o.trajectory + " --at SECONDS");
    }
    view.focal -= followed->Origin(positions, Eigen::Isometry3d::Identity(), a.plan.TrajectoryTime(k), warnings);
  }
  PrintWarnings(warnings);
  WriteToStdout(animation::JoinWords(
      animation::RenderWords(*a.scene.robot.robot, positions, view, !o.render.request.no_clamp)) + "\n");
}

// A range of frames' outputs, open: the colour and the numbered sequences asked for.
struct OpenOutputs {
  std::unique_ptr<video::FrameEncoder> colour;
  std::optional<video::NumberedFiles> depth, labels, mask, keypoints;

  animation::AnimationOutputs Pointers(int mask_dilate) {
    return {colour.get(), depth ? &*depth : nullptr, labels ? &*labels : nullptr, mask ? &*mask : nullptr, mask_dilate,
            keypoints ? &*keypoints : nullptr};
  }
};

// Opens every output into `outputs` for the frames of `range` (a worker's staged for its parent).
void OpenRange(const AnimateOptions& o, const PreparedAnimation& a, shard::FrameRange range,
               const video::Staging& staging, OpenOutputs& outputs, Warnings& warnings) {
  const render::RenderSettings& settings = a.scene.robot.settings;
  outputs.colour = video::OpenFrameEncoder(
      o.output, {settings.size.width, settings.size.height, a.plan.fps, range.first, staging}, warnings);
  for (const auto& [pattern, files] : {std::pair{&o.depth, &outputs.depth}, {&o.labels, &outputs.labels},
                                       {&o.mask, &outputs.mask}, {&o.keypoints, &outputs.keypoints}}) {
    if (!pattern->empty()) files->emplace(*pattern, range.first, staging);
  }
}

// Writes the link names of --labels, once for the whole animation.
void WriteLabelNames(const AnimateOptions& o, const PreparedAnimation& a, OutputPlan& outputs) {
  if (!o.labels.empty()) {
    outputs.Write(animation::LabelNamesPath(o.labels), image::LabelNamesJson(a.scene.robot.robot->LinkNames()));
  }
}

stream::ProgressBar::Display BarDisplay(const AnimateOptions& o) {
  return o.quiet ? stream::ProgressBar::Display::kNever : stream::ProgressBar::Display::kIfTerminal;
}

// Renders this shard's frames into the outputs `outputs` planned (prepared: checked and their folders
// made), every output opened before the first frame and appearing only when all are complete.
void WriteAnimation(const AnimateOptions& o, const shard::ShardChoice& choice, request::RenderSession& session,
                    const PreparedAnimation& a, OutputPlan& outputs, Warnings& warnings) {
  const shard::FrameRange range = shard::FramesOfShard(a.plan.frame_count, choice.shard);
  PrintShardLine(choice, range.size(), a.plan.frame_count, "frames", RangeText(range));

  a.frames->Positions(0, warnings);  // a pose's warnings are every frame's: print them first
  OpenOutputs open;
  OpenRange(o, a, range, {}, open, warnings);
  WriteLabelNames(o, a, outputs);
  PrintWarnings(warnings);   // --strict ends here, before any frame

  stream::ProgressBar bar(range.size(), "frames", BarDisplay(o));
  Warnings later;
  animation::RenderAnimation(*a.scene.robot.renderer, session.GlRenderer(a.scene.robot.settings.samples), *a.frames,
                             range, open.Pointers(o.mask_dilate), [&](std::int64_t done) { bar.Update(done); }, later);
  outputs.Commit();
  bar.Finish(WrittenText(o.output, range));
  PrintNewWarnings(warnings, later);
}

// Draws piece `piece` of `pieces` of the frames into files under the temporary names of `suffix`
// (left for the parent that chose it), calling `progress` with the frames of the piece done so far;
// returns how many frames the piece has.
std::int64_t DrawPiece(const AnimateOptions& o, request::RenderSession& session, const PreparedAnimation& a, int piece,
                       int pieces, const std::string& suffix, const std::function<void(std::int64_t)>& progress,
                       Warnings& warnings) {
  const shard::FrameRange range =
      shard::FramesOfShard(a.plan.frame_count, shard::CheckedShard(piece, pieces, "piece"));
  if (range.size() == 0) return 0;
  OpenOutputs open;
  OpenRange(o, a, range, {suffix, true}, open, warnings);
  animation::RenderAnimation(*a.scene.robot.renderer, session.GlRenderer(a.scene.robot.settings.samples), *a.frames,
                             range, open.Pointers(o.mask_dilate), progress, warnings);
  return range.size();
}

// A frame sequence drawn by `workers` (started with `suffix` as the temporary names of their files,
// the frames cut into `pieces`) and by this process beside them, taking pieces as they do: a worker
// fewer to start, read the model and upload it to the GL. Wait runs on a second thread; this one
// writes the link names, sums everyone's progress into its line and, once every piece is drawn,
// moves every frame's files into place (or, after an error or a signal, removes them).
void WriteByWorkers(const AnimateOptions& o, const std::string& suffix, request::RenderSession& session,
                    const PreparedAnimation& a, WorkerProcesses& workers, int pieces, OutputPlan& outputs,
                    Warnings& warnings) {
  const shard::FrameRange range{0, a.plan.frame_count};
  a.frames->Positions(0, warnings);
  std::vector<std::unique_ptr<video::NumberedFiles>> staged;
  for (const std::string* pattern : {&o.output, &o.depth, &o.labels, &o.mask, &o.keypoints}) {
    if (pattern->empty()) continue;
    staged.push_back(std::make_unique<video::NumberedFiles>(*pattern, 0, video::Staging{suffix, false}));
    staged.back()->Adopt(range.size());
  }
  WriteLabelNames(o, a, outputs);
  PrintWarnings(warnings);   // --strict ends here; the workers are stopped
  stream::ProgressBar bar(range.size(), "frames", BarDisplay(o));
  Warnings later, own;         // the workers' (Wait's thread) and this process's frames'
  DrawBesideWorkers(workers, [&](int piece, const std::function<void(std::int64_t)>& progress) {
    return DrawPiece(o, session, a, piece, pieces, suffix, progress, own);
  }, [&](std::int64_t done) { bar.Update(done); }, later);
  for (const auto& files : staged) files->Finish();
  outputs.Commit();
  bar.Finish(WrittenText(o.output, range));
  for (const std::string& message : own.messages()) later.Add(message);
  PrintNewWarnings(warnings, later);
}

// A worker process of a parent's `animate --jobs N` (the hidden --worker-pieces and
// --worker-output, a suffix): the frames of each piece the parent hands it, under the temporary names the
// parent moves into place; its progress on stdout, its warnings on stderr for the parent to gather.
void DrawPieces(const AnimateOptions& o, request::RenderSession& session, const PreparedAnimation& a,
                Warnings& warnings) {
  std::int64_t done = 0;
  while (const std::optional<int> piece = NextPiece()) {
    done += DrawPiece(o, session, a, *piece, o.jobs.worker_pieces, o.jobs.worker_output,
                      [&](std::int64_t written) { ReportImagesDone(done + written); }, warnings);
  }
  PrintWarningsBeforeError(warnings);   // the parent gathers them (and applies --strict)
}

// How many processes draw the animation (JobOptions::WorkerCount; with more than one, this one and
// one worker fewer): one for a video (one file, encoded in order), --print-frame or a shard of a
// larger job.
int WorkerCount(const AnimateOptions& o) {
  return o.jobs.WorkerCount(!o.print_frame.empty() || o.output.empty() ||
                            video::OutputFormatOf(o.output) != video::OutputFormat::kPngSequence ||
                            o.sharding.Choose().sharded());
}

// One animation (of the one MODEL, or of one of many bags) drawn through `session`, or by this
// process and `jobs` - 1 worker processes; `gl_loading` is the GL library being loaded (started
// here with the workers).
void RunOne(AnimateOptions& o, request::RenderSession& session, std::optional<std::future<void>>& gl_loading,
            int jobs) {
  request::RenderRequest& r = o.render.request;
  // MODEL given as a bag: its motion and the robot description it recorded
  std::optional<BagModel> bag_model;
  if (o.trajectory.empty() && motion::IsBag(o.model.path)) {
    o.trajectory = o.model.path;
    bag_model.emplace(o.model.path, o.description_topic);
    o.model_from_bag = true;
  }
  r.model = o.model.ToRequest();
  if (bag_model) r.model.path = bag_model->path();
  o.render.ParseJointWords();
  if (o.output.empty() && o.print_frame.empty()) {
    throw Error("animate: give the output with -o FILE: .mp4, .webm, .gif, .webp or a pattern such as "
                "frames/%05d.png");
  }
  // frame rate and size not given: the output format's (smaller for GIF)
  const video::FormatDefaults defaults =
      video::DefaultsFor(o.output.empty() ? video::OutputFormat::kMp4 : video::OutputFormatOf(o.output));
  if (o.fps.empty()) o.fps = FormatNumber(defaults.fps);
  if (r.size.empty() && r.camera_info.empty()) r.size = defaults.size;   // a calibration gives its own
  const shard::ShardChoice choice = ChooseShard(o);
  if (!o.depth.empty()) animation::CheckDepthPattern(o.depth, "--depth");
  if (!o.labels.empty()) animation::CheckLabelsPattern(o.labels, "--labels");
  if (!o.mask.empty()) animation::CheckPattern(o.mask, ".png", "--mask");
  dataset::CheckMaskDilate(o.mask_dilate, "--mask-dilate");
  if (!o.keypoints.empty()) animation::CheckPattern(o.keypoints, ".json", "--keypoints");
  // no output may be another output or an input; their folders are made (removed again on failure)
  OutputPlan outputs;
  if (o.print_frame.empty() && o.jobs.worker_pieces == 0) {
    request::AddRequestInputs(outputs, r);
    outputs.AddInput(o.trajectory, "--trajectory");
    animation::PlanOutput(outputs, o.output, "-o");
    if (!o.depth.empty()) animation::PlanOutput(outputs, o.depth, "--depth");
    if (!o.labels.empty()) {
      animation::PlanOutput(outputs, o.labels, "--labels");
      outputs.AddFile(animation::LabelNamesPath(o.labels), "the link names of --labels");
    }
    if (!o.mask.empty()) animation::PlanOutput(outputs, o.mask, "--mask");
    if (!o.keypoints.empty()) animation::PlanOutput(outputs, o.keypoints, "--keypoints");
    outputs.Prepare();
  }
  // workers start before this process reads the model, which they read too
  const std::string suffix = jobs > 1 ? ".part-" + RandomSuffix() : "";
  const int pieces = kFramePiecesPerWorker * jobs;
  std::optional<WorkerProcesses> workers;
  if (jobs > 1) {
    workers.emplace(jobs - 1, "animate", JobOptions::WorkerOptions(pieces, suffix), pieces);
    gl_loading = gl::StartLoadingGl(o.gl_options.Choice().backend);   // its thread with the stop signals blocked
  }

  Warnings warnings;
  WarnOfUnusedBagTopics(o.topic, o.description_topic, !o.trajectory.empty() && motion::IsBag(o.trajectory),
                        o.model_from_bag, "--trajectory", warnings);
  WarnOfUnusedMaskDilate(o.mask_dilate, o.mask, warnings);
  for (const auto& [given, option] : {std::pair{o.clamp, "--clamp"}, {o.strict_joints, "--strict-joints"}}) {
    if (given && o.trajectory.empty()) {
      WarnIgnored(warnings, option, "it decides how --trajectory's joints are drawn, and there is no --trajectory");
    }
  }
  try {
    // the encoder thread keeps a core busy while frames are drawn, unless drawing outweighs it
    // (set while no other thread runs: before the encoder opens and the GL context reads it); once
    bool gl_ready = false;
    const auto ready_gl = [&](const PreparedAnimation& a) {
      if (std::exchange(gl_ready, true)) return;
      gl_loading->wait();
      const std::string rasteriser = gl::LeaveCoresToOtherThreads(1, a.scene.robot.renderer->scene().triangle_count());
      if (o.gl_options.verbose && !rasteriser.empty() && !workers) {
        std::fprintf(stderr, "urdfsnap: %s\n", rasteriser.c_str());   // else the workers say it
      }
    };
    PreparedAnimation animation;
    PrepareAnimation(o, session, animation, warnings, [&](const PreparedAnimation& a) {
      ready_gl(a);
      WarmUpGl(session, a);
    });
    if (!o.print_frame.empty()) return PrintFrame(o, animation, warnings);
    if (workers) {
      if (animation.fit != render::Fit::kNone) workers->Tell(ViewLine(animation.frames->fitted_view()));
      ready_gl(animation);
      return WriteByWorkers(o, suffix, session, animation, *workers, pieces, outputs, warnings);
    }
    ready_gl(animation);
    if (o.jobs.worker()) return DrawPieces(o, session, animation, warnings);
    WriteAnimation(o, choice, session, animation, outputs, warnings);
  } catch (const Error& e) {
    PrintWarningsBeforeError(warnings);
    if (bag_model) throw Error(bag_model->Located(e.what()));
    throw;
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
}

// MODEL and the words after it that are bags, when MODEL is one (`animate a.mcap b.mcap ...`).
std::vector<std::string> BagsGiven(const ModelSource& model) {
  if (!motion::IsBag(model.path)) return {};
  std::vector<std::string> bags{model.path};
  for (const std::string& word : model.xacro_words) {
    if (word.find(":=") == std::string::npos && motion::IsBag(word)) bags.push_back(word);
  }
  return bags;
}

void Run(AnimateOptions& o) {
  if (o.jobs.worker()) StopWhenParentEnds();
  ReuseFreedFrameMemory();
  const gl::BackendChoice backend = o.gl_options.Choice();
  const std::vector<std::string> bags = BagsGiven(o.model);
  const int jobs = bags.size() < 2 ? WorkerCount(o) : 1;   // each of many bags in this process
  // one process: Mesa loads while the model is read (before workers block the stop signals)
  std::optional<std::future<void>> gl_loading;
  if (jobs == 1) gl_loading = gl::StartLoadingGl(backend.backend);
  // with workers, their --verbose lines are said (once, by WorkerProcesses), not this process's same ones
  gl::BackendChoice own_backend = backend;
  if (jobs > 1) own_backend.on_context = nullptr;
  request::RenderSession session(own_backend);
  if (bags.size() < 2) return RunOne(o, session, gl_loading, jobs);
  if (!o.trajectory.empty() || !o.print_frame.empty()) {
    throw Error("animate: " + std::to_string(bags.size()) + " bags are animated each with its own motion and "
                "description; --trajectory and --print-frame take one MODEL");
  }
  std::vector<std::string> words;   // the xacro arguments, the same for every bag
  for (const std::string& word : o.model.xacro_words) {
    if (std::find(bags.begin(), bags.end(), word) == bags.end()) words.push_back(word);
  }
  AnimateEachBag(bags, o.output, [&](const std::string& bag) {
    AnimateOptions one = o;
    one.model.path = bag;
    one.model.xacro_words = words;
    const std::string stem = BagStem(bag);
    one.output = WithStem(o.output, stem);
    one.depth = WithStem(o.depth, stem);
    one.labels = WithStem(o.labels, stem);
    RunOne(one, session, gl_loading, 1);
  });
}

}  // namespace

void AddAnimateCommand(CLI::App& app) {
  auto o = std::make_shared<AnimateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "animate", "Render a trajectory, a recorded bag or a turntable to a video, GIF, WebP or PNG sequence");
  o->model.AddOptions(*cmd);
  cmd->add_option("-o,--output", o->output,
                  "file to write, by extension: .mp4 (H.264), .webm (VP9), .gif, .webp (animated) or "
                  "a PNG sequence such as frames/%05d.png (numbered from 0; each frame as `render` "
                  "writes it); missing folders are made. A frame sequence splits over workers "
                  "with --shard: each writes a contiguous range of the files, named as in the whole "
                  "animation, from the same camera. Several bags as MODEL (animate a.mcap b.mcap ... "
                  "-o out/{stem}.mp4) are each animated with the same view and options into the file "
                  "{stem} (the bag's name) makes, one line per bag and a summary; a bag that fails gets "
                  "its error line, the others are still animated, and the run then exits with status 2");
  cmd->add_option("--trajectory", o->trajectory,
                  "the motion: a CSV table (time,<joint>,...), a JointTrajectory, MoveIt "
                  "RobotTrajectory/DisplayTrajectory or JointState stream in YAML/JSON (as `ros2 "
                  "topic echo` prints), or a ROS 2 bag (.mcap or .db3 file, or a rosbag2 folder: split, "
                  "zstd-compressed, MCAP or SQLite storage)");
  cmd->add_option("--topic", o->topic,
                  "the sensor_msgs/msg/JointState topic of a bag (default /joint_states)");
  cmd->add_option("--description-topic", o->description_topic,
                  "when MODEL is a bag (then also the trajectory): the std_msgs/msg/String topic "
                  "whose first message is the robot description, as RViz's RobotModel display "
                  "reads it (default /robot_description)");
  cmd->add_flag("--clamp", o->clamp,
                "clamp the trajectory's values to the joint limits as joint_state_publisher's "
                "slider would (default: drawn as recorded, with one warning per joint that leaves "
                "its limits)");
  cmd->add_flag("--strict-joints", o->strict_joints,
                "stop at a joint of the trajectory that the model does not have (default: such "
                "joints are ignored with one warning, as robot_state_publisher ignores them)");
  cmd->add_option("--fps", o->fps, "frames per second (default 30; 15 for .gif); frame k shows time k/fps");
  cmd->add_option("--speed", o->speed,
                  "playback speed of the trajectory: 2 plays it twice as fast (default 1)");
  cmd->add_flag("--turntable", o->turntable,
                "turn the camera's yaw once around over the animation; without --trajectory the "
                "still pose turns for --duration seconds");
  cmd->add_option("--start", o->start,
                  "play the trajectory from this time: seconds from its start, or a stamp "
                  "(seconds since 1970, from 1e9 up) for messages timed by their stamps; frame k "
                  "shows start + k * speed / fps");
  cmd->add_option("--end", o->end, "play the trajectory up to this time (as --start)");
  cmd->add_option("--duration", o->duration,
                  "length in seconds (default: the trajectory's length / --speed, past its end the "
                  "last pose holds; a still turntable 6)");
  cmd->add_option("--depth", o->depth,
                  "also write the depth image of every frame: a pattern such as depth/%05d.png "
                  "(16-bit mm) or depth/%05d.npy (float32 m), as `render --depth` writes them");
  cmd->add_option("--labels", o->labels,
                  "also write the link-label image of every frame: a pattern such as "
                  "labels/%05d.png, as `render --labels` writes them, with the link names once in "
                  "the pattern's name without the number, .json (labels/labels.json; each shard writes "
                  "the same one)");
  cmd->add_option("--mask", o->mask,
                  "also write the robot's mask of every frame: a pattern such as masks/%05d.png, "
                  "as `render --mask` writes it (8-bit, 255 on the robot)");
  cmd->add_option("--mask-dilate", o->mask_dilate, "grow each --mask by N pixels (a disc), 0 to 1000 (default 0)");
  cmd->add_option("--keypoints", o->keypoints,
                  "also write every frame's keypoints: a pattern such as keypoints/%05d.json, each "
                  "file as `render --keypoints` writes it (link frames' and joint origins' pixels, "
                  "depth, visibility, and the camera)");
  cmd->add_option("--print-frame", o->print_frame,
                  "write nothing; print the options that make `render` (with the same MODEL and "
                  "options, without --fit) draw frame K byte for byte: the view and every joint");
  cmd->add_flag("-q,--quiet", o->quiet, "no progress bar (it is shown only on a terminal anyway)");
  o->sharding.AddOptions(*cmd, "frames of a frame sequence (a video is never split)");
  o->render.AddOptions(*cmd);
  o->displays.AddOptions(*cmd);
  o->camera.AddOptions(*cmd, "each frame's moment");
  o->gl_options.AddOptions(*cmd, ", and how many threads llvmpipe rasterises on beside the encoder");
  o->jobs.AddOptions(*cmd, "draw a frame sequence in N processes at once (this one and N-1 workers), each taking "
                          "contiguous runs of its frames as it finishes the last (default: one per core this "
                          "process may use; 1: in this process). A video, --shard, or a model on standard input: "
                          "one process");
  // a stopping signal ends the command after the staged frames and the folders made are removed
  cmd->callback([o] { RunStoppable([o] { Run(*o); }); });
}

}  // namespace urdfsnap::cli
