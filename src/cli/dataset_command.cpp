// `urdfsnap dataset MODEL -o DIR --count N --seed S`: labelled training data (colour, depth, link
// labels, COCO annotations with joint keypoints) of a robot in random poses from random cameras;
// see dataset/dataset_writer.h for the files.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <string_view>
#include <limits>
#include <memory>

#include "cli/command.h"
#include "cli/frame_memory.h"
#include "cli/gl_options.h"
#include "cli/job_options.h"
#include "cli/model_source.h"
#include "cli/pieces_beside_workers.h"
#include "cli/shard_options.h"
#include "cli/worker_processes.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/number_text.h"
#include "common/random_suffix.h"
#include "dataset/camera_poses_file.h"
#include "dataset/dataset_writer.h"
#include "gl/gl_context.h"
#include "gl/rasteriser_threads.h"
#include "model/forward_kinematics.h"
#include "request/render_session.h"
#include "request/value_parsing.h"
#include "shard/shard_spec.h"
#include "stream/progress_bar.h"

namespace urdfsnap::cli {

namespace {

struct DatasetOptions {
  ModelSource model;
  std::string output;
  std::string count, seed = "0", distance, elevation;
  std::string camera_poses;   // a file of camera poses, cycled through
  bool quiet = false;
  ShardOptions sharding;
  JobOptions jobs;            // worker processes writing the samples; a worker's pieces and suffix
  request::RenderRequest request;
  GlOptions gl_options;
};

// The pieces the samples are cut into per drawing process: a sample costs several frames' work
// (colour, labels, depth, three PNGs, its COCO entries), so few pieces keep the processes within
// one of each other.
constexpr int kSamplePiecesPerWorker = 4;

// By default a robot of fewer triangles than this is drawn in one process (its render and writer
// threads keep two cores busy): mrm (812 triangles) in two processes (this one beside a worker)
// took ~15 % more CPU and was no faster (400 samples, 5 alternating rounds at load 2.8-3.3:
// 1.61-1.82 s against 1.64-1.76 s), Panda (126,598) gains from them (docs/benchmarks.md, "Dataset
// samples"). llvmpipe's boundary between light and raster-bound scenes (gl/rasteriser_threads.h).
constexpr std::size_t kOneProcessBelowTriangles = gl::kRasterBoundTriangles;

// render's options that a dataset draws per sample, or that a dataset has no use for
constexpr std::string_view kDrawnPerSample[] = {"yaw", "pitch", "distance", "focal", "fit", "fit-margin",
                                                "camera-pose", "underlay", "underlay-alpha"};

// render's view and display options less kDrawnPerSample.
void AddSceneOptions(CLI::App& command, request::RenderRequest& request) {
  const auto drawn = [](std::string_view name) {
    return std::find(std::begin(kDrawnPerSample), std::end(kDrawnPerSample), name) != std::end(kDrawnPerSample);
  };
  for (const request::TextOption& option : request::TextOptions()) {
    if (!drawn(option.name)) command.add_option(request::CommandLineLabel(option.name), request.*option.field, option.help);
  }
  for (const request::FlagOption& option : request::FlagOptions()) {
    if (!drawn(option.name)) command.add_flag(request::CommandLineLabel(option.name), request.*option.field, option.help);
  }
}

// "MIN:MAX" with MIN <= MAX, both within [low, high].
dataset::Interval ParseInterval(const std::string& text, const std::string& option, double low, double high) {
  const size_t colon = text.find(':');
  dataset::Interval range;
  if (colon == std::string::npos || !ParseNumber(text.substr(0, colon), range.low) ||
      !ParseNumber(text.substr(colon + 1), range.high) || range.low > range.high || range.low < low ||
      range.high > high) {
    throw Error(option + " '" + text + "': expected MIN:MAX, MIN not above MAX, both from " + FormatNumber(low) +
                " to " + FormatNumber(high));
  }
  return range;
}

// A whole number from `low` to `high`.
double ParseWhole(const std::string& text, const std::string& option, double low, double high) {
  const double value = request::ParseInRange(text, option, low, high);
  if (value != std::floor(value)) throw Error(option + " '" + text + "': expected a whole number");
  return value;
}

// The files of COCO entries of piece `piece` that a worker writes for its parent.
dataset::CocoParts PieceParts(const dataset::DatasetSpec& spec, const std::string& suffix, int piece) {
  const std::string stem =
      (std::filesystem::path(spec.folder) / spec.annotations_file).string() + suffix + "-" + std::to_string(piece);
  return {stem + ".images", stem + ".annotations"};
}

// Writes the samples of piece `piece` of `pieces`, and their COCO entries in the piece's files
// (named with `suffix`, left for the parent), calling `progress` with the piece's samples written
// so far; returns how many samples the piece has. The sample folders must have been made.
std::int64_t DrawPiece(const render::RobotRenderer& renderer, gl::SceneRenderer& gl,
                       const render::CameraSettings& camera, dataset::DatasetSpec spec, int piece, int pieces,
                       const std::string& suffix, const std::function<void(std::int64_t)>& progress,
                       Warnings& warnings) {
  spec.range = shard::FramesOfShard(spec.count, shard::CheckedShard(piece, pieces, "piece"));
  const dataset::CocoParts parts = PieceParts(spec, suffix, piece);
  AtomicFile images(parts.images), annotations(parts.annotations);
  dataset::WriteSamples(renderer, gl, camera, spec, images, annotations, progress, warnings);
  images.Commit();
  annotations.Commit();
  return spec.range.size();
}

// A worker process of a parent's `dataset --jobs N` (the hidden --worker-pieces and
// --worker-output, a suffix): the samples of each piece the parent hands it, and their COCO entries in the
// piece's files; its progress on stdout, its warnings on stderr for the parent to gather.
void DrawPieces(const DatasetOptions& o, const render::RobotRenderer& renderer, gl::SceneRenderer& gl,
                const render::CameraSettings& camera, const dataset::DatasetSpec& spec, Warnings& warnings) {
  dataset::MakeSampleFolders(spec.folder);
  std::int64_t done = 0;
  while (const std::optional<int> piece = NextPiece()) {
    done += DrawPiece(renderer, gl, camera, spec, *piece, o.jobs.worker_pieces, o.jobs.worker_output,
                      [&](std::int64_t written) { ReportImagesDone(done + written); }, warnings);
  }
  PrintWarningsBeforeError(warnings);   // the parent gathers them (and applies --strict)
}

// The files of every piece's COCO entries, removed when the parent is done with them (or fails).
class PieceFiles {
 public:
  PieceFiles(const dataset::DatasetSpec& spec, const std::string& suffix, int pieces)
      : folder_(spec.folder), suffix_(suffix) {
    for (int piece = 1; piece <= pieces; ++piece) parts_.push_back(PieceParts(spec, suffix, piece));
  }
  // with the temporary files of a worker stopped while writing one
  ~PieceFiles() { RemoveFilesNamedWith(folder_, suffix_); }
  PieceFiles(const PieceFiles&) = delete;
  PieceFiles& operator=(const PieceFiles&) = delete;

  const std::vector<dataset::CocoParts>& parts() const { return parts_; }

 private:
  std::string folder_, suffix_;
  std::vector<dataset::CocoParts> parts_;
};

void Run(DatasetOptions& o) {
  if (o.jobs.worker()) StopWhenParentEnds();
  ReuseFreedFrameMemory();
  const gl::BackendChoice backend = o.gl_options.Choice();
  const int most_jobs = o.jobs.WorkerCount(o.sharding.Choose().sharded());
  // by default the number of processes waits for the scene (see kOneProcessBelowTriangles): 0 until
  // then; --jobs N is N from the start
  int jobs = o.jobs.jobs > 0 || most_jobs == 1 ? most_jobs : 0;
  // one process: Mesa loads while the model is read (before workers block the stop signals)
  std::optional<std::future<void>> gl_loading;
  if (jobs == 1) gl_loading = gl::StartLoadingGl(backend.backend);
  request::RenderRequest& r = o.request;
  r.model = o.model.ToRequest();
  if (o.count.empty()) throw Error("dataset: give the number of samples with --count N");
  dataset::DatasetSpec spec;
  spec.folder = o.output;
  spec.count = static_cast<std::int64_t>(ParseWhole(o.count, "--count", 1, 1e9));
  spec.seed = static_cast<std::uint64_t>(ParseWhole(o.seed, "--seed", 0, 9007199254740992.0));
  spec.elevation = ParseInterval(o.elevation.empty() ? "0:60" : o.elevation, "--elevation", -90, 90);
  // the cameras: from the poses file, at the camera frame itself, or random on a sphere
  if (!o.camera_poses.empty()) {
    spec.camera_poses = dataset::ReadCameraPoses(o.camera_poses);
  } else if (!r.camera_frame.empty()) {
    spec.camera_poses = {Eigen::Isometry3d::Identity()};
  }
  if (!spec.camera_poses.empty() && (!o.distance.empty() || !o.elevation.empty())) {
    throw Error(std::string(o.distance.empty() ? "--elevation" : "--distance") +
                " places random cameras around the robot; the cameras are given by " +
                (o.camera_poses.empty() ? "--camera-frame" : "--camera-poses"));
  }
  const shard::ShardChoice choice = o.sharding.Choose();
  spec.range = shard::FramesOfShard(spec.count, choice.shard);
  spec.annotations_file = choice.sharded() ? "annotations." + std::to_string(choice.shard.index) + "-of-" +
                                                 std::to_string(choice.shard.count) + ".json"
                                           : "annotations.json";
  PrintShardLine(choice, spec.range.size(), spec.count, "samples",
                 spec.range.size() ? "samples " + std::to_string(spec.range.first) + " to " +
                                         std::to_string(spec.range.end - 1)
                                   : "no samples: fewer samples than shards");

  // with --jobs N > 1, this process draws beside N-1 workers, which start before it reads the
  // model (they read it too); Mesa loads after they block the stop signals (its thread then has
  // them blocked too)
  std::optional<PieceFiles> piece_files;
  std::optional<WorkerProcesses> workers;
  std::string suffix;
  int pieces = 0;
  const auto start_workers = [&] {
    if (jobs > 1) {
      suffix = ".part-" + RandomSuffix();
      pieces = kSamplePiecesPerWorker * jobs;
      piece_files.emplace(spec, suffix, pieces);
      workers.emplace(jobs - 1, "dataset", JobOptions::WorkerOptions(pieces, suffix), pieces);
    }
    gl_loading = gl::StartLoadingGl(backend.backend);
  };
  if (jobs > 1) start_workers();

  Warnings warnings;
  try {
    // the camera: --camera-info's, or the view's field of view at --size; placed per sample
    request::RenderRequest posed = r;
    posed.camera_pose = "0,0,0,0,0,0,1";
    render::RenderSettings settings;
    std::shared_ptr<const model::Robot> robot;
    {
      request::RenderSession session;
      const request::Prepared prepared = session.Prepare(posed, request::CommandLineLabel, warnings);
      settings = prepared.settings;
      robot = prepared.robot;
    }
    settings.scene.fixed_frame.clear();   // cameras are placed in the root link's frame
    const render::RobotRenderer renderer(robot, settings.scene, warnings);
    // an unknown --camera-frame is named before anything is written
    renderer.CameraPose(model::ComputeLinkPoses(*robot, std::vector<double>(robot->joints().size(), 0.0)),
                        *settings.camera);
    if (spec.camera_poses.empty()) {
      spec.distance = o.distance.empty() ? dataset::DefaultDistance(renderer, *settings.camera->model)
                                         : ParseInterval(o.distance, "--distance", 1e-3, 1e6);
    }
    PrintWarnings(warnings);
    if (jobs == 0) {
      const std::size_t triangles = renderer.scene().triangle_count();
      jobs = triangles < kOneProcessBelowTriangles ? 1 : most_jobs;
      if (o.gl_options.verbose) {
        std::fprintf(stderr, "urdfsnap: %zu triangles: %s\n", triangles,
                     jobs == 1 ? "one process (--jobs N for worker processes)"
                               : (std::to_string(jobs) + " processes (this one and its workers)").c_str());
      }
      start_workers();
    }
    Warnings later;
    // the writer thread keeps a core busy while samples are drawn, unless drawing outweighs it
    // (as animate decides; set while no other thread runs: before the GL context reads it)
    gl_loading->wait();
    const std::string rasteriser = gl::LeaveCoresToOtherThreads(1, renderer.scene().triangle_count());
    // with workers, they say their --verbose lines (passed on once), not this process the same
    if (o.gl_options.verbose && !rasteriser.empty() && !workers) {
      std::fprintf(stderr, "urdfsnap: %s\n", rasteriser.c_str());
    }
    gl::BackendChoice own_backend = backend;
    if (workers) own_backend.on_context = nullptr;
    gl::SceneRenderer gl(settings.samples, own_backend);
    if (o.jobs.worker()) return DrawPieces(o, renderer, gl, *settings.camera, spec, later);
    stream::ProgressBar bar(spec.range.size(), "samples",
                            o.quiet ? stream::ProgressBar::Display::kNever : stream::ProgressBar::Display::kIfTerminal);
    const auto progress = [&](std::int64_t done) { bar.Update(done); };
    if (workers) {
      dataset::MakeSampleFolders(spec.folder);
      Warnings own;   // this process's samples' (Wait's thread adds the workers' to `later`)
      DrawBesideWorkers(*workers, [&](int piece, const std::function<void(std::int64_t)>& piece_progress) {
        return DrawPiece(renderer, gl, *settings.camera, spec, piece, pieces, suffix, piece_progress, own);
      }, progress, later);
      for (const std::string& message : own.messages()) later.Add(message);
      dataset::WriteCocoFile(*robot, spec, piece_files->parts());
    } else {
      dataset::WriteDataset(renderer, gl, *settings.camera, spec, progress, later);
    }
    bar.Finish();
    PrintWarnings(later);
    std::fprintf(stderr, "urdfsnap: %lld samples of '%s' in %s (%s)\n", static_cast<long long>(spec.range.size()),
                 robot->name().c_str(), spec.folder.c_str(), spec.annotations_file.c_str());
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
}

}  // namespace

void AddDatasetCommand(CLI::App& app) {
  auto o = std::make_shared<DatasetOptions>();
  CLI::App* cmd = app.add_subcommand(
      "dataset", "Write labelled training data: random poses from random cameras, with depth, labels and COCO");
  o->model.AddOptions(*cmd);
  cmd->add_option("-o,--output", o->output,
                  "folder to write: images/, depth/ and labels/ (NNNNNN.png each) and annotations.json "
                  "(COCO; annotations.K-of-N.json for shard K of N)")
      ->required();
  cmd->add_option("--count", o->count, "number of samples in the dataset (every shard's together)");
  cmd->add_option("--seed", o->seed, "random seed: the same seed writes the same bytes (default 0)");
  cmd->add_option("--distance", o->distance,
                  "camera distance from the robot's centre MIN:MAX in m (default 1 to 2 times the "
                  "distance at which the zero pose's bounding sphere fills the image height)");
  cmd->add_option("--elevation", o->elevation,
                  "camera elevation above the horizontal MIN:MAX in degrees (default 0:60)");
  cmd->add_option("--camera-poses", o->camera_poses,
                  "FILE: the cameras instead of random ones, one pose of the optical frame per line, "
                  "X Y Z QX QY QZ QW (m; spaces or commas; '#' comments), in the root link's frame "
                  "or --camera-frame's; sample k uses line k modulo their number");
  cmd->add_flag("-q,--quiet", o->quiet, "no progress bar (it is shown only on a terminal anyway)");
  o->sharding.AddOptions(*cmd, "samples");
  AddSceneOptions(*cmd, o->request);
  o->gl_options.AddOptions(*cmd, ", and how many threads llvmpipe rasterises on beside the writer");
  o->jobs.AddOptions(*cmd, "write the samples in N processes at once (this one and N-1 workers), each taking "
                          "contiguous runs of them as it finishes the last, into one annotations.json (default: "
                          "one per core this process may use, or this process alone for a robot of fewer than "
                          "20,000 triangles, whose drawing and writing threads keep two cores busy; 1: in this "
                          "process). With --shard, or a model on standard input, one process");
  // a stopping signal ends the command after the pieces' COCO entry files are removed
  cmd->callback([o] { RunStoppable([o] { Run(*o); }); });
}

}  // namespace urdfsnap::cli
