// `urdfsnap animate`: MODEL + a trajectory (CSV, ROS messages in YAML/JSON, an MCAP bag) and/or a
// turntable → MP4, WebM, GIF, animated WebP or a PNG sequence, with depth and label sequences from
// the same frames. Every output appears only when complete; --print-frame K instead prints the
// `render` options that make frame K.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "animation/animation_frames.h"
#include "animation/frame_reproduction.h"
#include "animation/render_animation.h"
#include "animation/sequence_outputs.h"
#include "bag/joint_state_bag.h"
#include "cli/command.h"
#include "cli/gl_options.h"
#include "cli/model_source.h"
#include "cli/render_options.h"
#include "cli/shard_options.h"
#include "common/atomic_file.h"
#include "common/created_folders.h"
#include "common/error.h"
#include "common/number_text.h"
#include "gl/gl_context.h"
#include "gl/rasteriser_threads.h"
#include "model/joint_values.h"
#include "motion/frame_plan.h"
#include "motion/frame_poses.h"
#include "motion/trajectory_file.h"
#include "render/frame_files.h"
#include "request/render_session.h"
#include "request/value_parsing.h"
#include "shard/shard_assignment.h"
#include "video/frame_encoder.h"
#include "video/frame_files.h"

namespace urdfsnap::cli {

namespace {

// How long a turntable of a still pose lasts when --duration does not say.
constexpr double kStillTurntableSeconds = 6;

struct AnimateOptions {
  ModelSource model;
  std::string output;
  std::string trajectory;
  std::string topic = bag::kDefaultJointStateTopic;
  std::string fps = "30", speed, duration;  // checked as render checks its numbers
  bool turntable = false;
  std::string depth, labels;  // optional depth and link-label sequences (patterns)
  std::string print_frame;    // a frame number: print its render options instead of writing
  bool quiet = false;
  ShardOptions sharding;      // a frame sequence's contiguous range of frames
  RenderOptions render;
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
  if (o.trajectory.empty()) {
    if (!o.turntable) {
      throw Error("animate: nothing moves: give --trajectory FILE, --turntable or both");
    }
    if (speed) throw Error("animate: --speed plays a trajectory faster or slower; there is no --trajectory");
    return motion::PlanStill(duration.value_or(kStillTurntableSeconds), fps);
  }
  return motion::PlanFrames(trajectory, fps, speed.value_or(1), duration);
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

void Run(AnimateOptions& o) {
  const gl::BackendChoice backend = o.gl_options.Choice();
  // the encoder thread keeps a core busy while frames are drawn (before any thread starts)
  const std::string rasteriser = gl::LeaveCoresToOtherThreads(1);
  if (o.gl_options.verbose && !rasteriser.empty()) std::fprintf(stderr, "urdfsnap: %s\n", rasteriser.c_str());
  const auto gl_loading = gl::StartLoadingGl(backend.backend);  // overlaps loading Mesa with reading the model
  request::RenderRequest& r = o.render.request;
  r.model = o.model.ToRequest();
  o.render.ParseJointWords();
  if (o.output.empty() && o.print_frame.empty()) {
    throw Error("animate: give the output with -o FILE: .mp4, .webm, .gif, .webp or a pattern such as "
                "frames/%05d.png");
  }
  const shard::ShardChoice choice = ChooseShard(o);
  if (!o.depth.empty()) animation::CheckDepthPattern(o.depth, "--depth");
  if (!o.labels.empty()) animation::CheckLabelsPattern(o.labels, "--labels");

  Warnings warnings;
  try {
    // render's settings with the view as given (--fit is applied over every frame below)
    const request::OptionLabel label = [](std::string_view name) { return "--" + std::string(name); };
    request::RenderRequest unfitted = r;
    unfitted.fit = false;
    render::RenderSettings settings;
    std::shared_ptr<const model::Robot> robot;
    {
      request::RenderSession session;
      settings = session.ResolveSettings(unfitted, label, warnings);
      robot = session.LoadRobot(r.model, warnings);
    }
    const render::Fit fit =
        !r.fit ? render::Fit::kNone : r.focal.empty() ? render::Fit::kFit : render::Fit::kKeepFocal;
    const render::RobotRenderer renderer(robot, settings.scene, warnings);

    motion::Trajectory trajectory;
    if (!o.trajectory.empty()) trajectory = motion::ReadTrajectory(o.trajectory, {o.topic}, warnings);
    const motion::FramePlan plan = Plan(o, trajectory);
    // joints the trajectory does not name: --joints, then -j, as render takes them
    model::NamedValues defaults;
    if (!r.joint_file.empty()) defaults = model::ReadJointFile(r.joint_file);
    defaults.insert(defaults.end(), r.joints.begin(), r.joints.end());
    const motion::FramePoses poses(*robot, trajectory, defaults, !r.no_clamp, warnings);
    const animation::AnimationFrames frames(renderer, plan, poses,
                                            {settings.view, settings.size, fit, o.turntable, settings.camera},
                                            warnings);

    if (!o.print_frame.empty()) {
      const std::int64_t k = FrameNumber(o.print_frame, plan);
      const std::vector<double> positions = frames.Positions(k, warnings);
      PrintWarnings(warnings);
      WriteToStdout(animation::JoinWords(animation::RenderWords(*robot, positions, frames.View(k), !r.no_clamp)) + "\n");
      return;
    }

    const shard::FrameRange range = shard::FramesOfShard(plan.frame_count, choice.shard);
    PrintShardLine(choice, range.size(), plan.frame_count, "frames", RangeText(range));

    // every output opened (and so checked writable) before the first frame
    frames.Positions(0, warnings);  // a pose's warnings are every frame's: print them first
    CreatedFolders folders;
    for (const std::string* file : {&o.output, &o.depth, &o.labels}) {
      if (!file->empty()) folders.MakeParents(*file);
    }
    const auto encoder = video::OpenFrameEncoder(
        o.output, {settings.size.width, settings.size.height, plan.fps, range.first}, warnings);
    std::optional<video::FrameFiles> depth, labels;
    std::optional<AtomicFile> label_names;
    if (!o.depth.empty()) depth.emplace(o.depth, range.first);
    if (!o.labels.empty()) {
      labels.emplace(o.labels, range.first);
      label_names.emplace(animation::LabelNamesPath(o.labels));
      label_names->Write(render::LabelNamesJson(*robot));
    }
    PrintWarnings(warnings);   // --strict ends here, before any frame

    gl::Renderer gl(settings.samples, backend);
    stream::ProgressBar bar(range.size(), "frames",
                            o.quiet ? stream::ProgressBar::Display::kNever
                                    : stream::ProgressBar::Display::kIfTerminal);
    Warnings later;
    animation::RenderAnimation(renderer, gl, frames, range,
                               {encoder.get(), depth ? &*depth : nullptr, labels ? &*labels : nullptr},
                               &bar, later);
    if (label_names) label_names->Commit();
    folders.Keep();
    bar.Finish(WrittenText(o.output, range));
    PrintNewWarnings(warnings, later);
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
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
                  "animation, from the same camera");
  cmd->add_option("--trajectory", o->trajectory,
                  "the motion: a CSV table (time,<joint>,...), a JointTrajectory, MoveIt "
                  "RobotTrajectory/DisplayTrajectory or JointState stream in YAML/JSON (as `ros2 "
                  "topic echo` prints), or a ROS 2 bag (.mcap file or rosbag2 folder)");
  cmd->add_option("--topic", o->topic,
                  "the sensor_msgs/msg/JointState topic of a bag (default /joint_states)");
  cmd->add_option("--fps", o->fps, "frames per second (default 30); frame k shows time k/fps");
  cmd->add_option("--speed", o->speed,
                  "playback speed of the trajectory: 2 plays it twice as fast (default 1)");
  cmd->add_flag("--turntable", o->turntable,
                "turn the camera's yaw once around over the animation; without --trajectory the "
                "still pose turns for --duration seconds");
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
  cmd->add_option("--print-frame", o->print_frame,
                  "write nothing; print the options that make `render` (with the same MODEL and "
                  "options, without --fit) draw frame K byte for byte: the view and every joint");
  cmd->add_flag("-q,--quiet", o->quiet, "no progress bar (it is shown only on a terminal anyway)");
  o->sharding.AddOptions(*cmd, "frames of a frame sequence (a video is never split)");
  o->render.AddOptions(*cmd);
  o->gl_options.AddOptions(*cmd, ", and how many threads llvmpipe rasterises on beside the encoder");
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
