// `urdfsnap docs`: a robot's documentation page (README.md, index.html and their pictures) written
// into a folder that appears only when complete, or `--check`ed against a fresh one for CI. The
// pictures are made by worker processes at once (--jobs), each a shard of them; this process then
// writes the documents.
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include "cli/command.h"
#include "cli/gl_options.h"
#include "cli/job_options.h"
#include "cli/model_source.h"
#include "cli/render_options.h"
#include "cli/shard_options.h"
#include "cli/worker_processes.h"
#include "common/error.h"
#include "docs/animation_output.h"
#include "docs/page_check.h"
#include "docs/page_folder.h"
#include "docs/page_shard.h"
#include "docs/page_writer.h"
#include "gl/gl_context.h"
#include "request/render_session.h"
#include "request/request_inputs.h"
#include "stream/progress_bar.h"

namespace urdfsnap::cli {

namespace {

// render's options that cannot work on a page whose every picture is fitted to what it shows
// through the orbit view: each is refused with the reason (--fit, which docs always does, warned
// of), not left out of the command line, so that a user who gives one learns why.
constexpr std::string_view kNotOnDocs[] = {"distance", "fit", "camera-info", "camera-frame", "camera-pose",
                                           "near", "far", "underlay", "underlay-alpha", "distort"};

struct DocsOptions {
  ModelSource model;
  std::string output, check;
  std::vector<std::string> section_globs;
  std::string animations, stills = "webp";
  bool quiet = false;
  ShardOptions sharding;            // a contiguous part of the page's pictures and animations
  JobOptions jobs;                  // worker processes making the pictures; a worker's pieces and folder
  RenderOptions render;             // the pose (-j, --joints) and the view and display options
  std::vector<std::string> refused; // the kNotOnDocs options given, in order
  GlOptions gl_options;
};

// Throws for the first refused option given (a warning for --fit), and for --joints naming no
// file: before, it was the section filter --sections is now.
void CheckOptions(const DocsOptions& o, Warnings& warnings) {
  for (const std::string& name : o.refused) {
    if (name == "fit") {
      WarnIgnored(warnings, "--fit", "docs always fits each picture to what it shows");
    } else if (name == "distance") {
      throw Error("docs: --distance does not apply: each picture of the page is fitted to what it shows "
                  "(choose the direction with --yaw and --pitch, the point looked at with --focal)");
    } else {
      throw Error("docs: --" + name + " does not apply: the page's pictures are drawn through the orbit view "
                  "(--yaw, --pitch, --focal, --fov); a calibrated camera is for render, animate and snapshot");
    }
  }
  const std::string& file = o.render.request.joint_file;
  if (std::error_code error; file.empty() || std::filesystem::exists(file, error)) return;
  throw Error("--joints '" + file + "': no such joint file (--joints is the page's pose as in render, a "
              "YAML/JSON joint file; to give sections only to some joints use --sections '" + file + "')");
}

// Prints what --check found and ends with status 1 when the page is stale.
void Report(const std::string& folder, const std::vector<std::string>& differences) {
  if (differences.empty()) return WriteToStdout(folder + ": up to date\n");
  std::string text = folder + ": stale, " + std::to_string(differences.size()) + " difference" +
                     (differences.size() == 1 ? "" : "s") + " from a fresh page:\n";
  for (const std::string& difference : differences) text += "  " + difference + "\n";
  text += "regenerate it: the same command with -o " + folder + " instead of --check " + folder + "\n";
  WriteToStdout(text);
  throw CommandExit{1};
}

// The pieces `docs --jobs N` cuts a page into per worker (contiguous runs of its pictures and
// animations, each worker taking the next as it finishes one): enough that the workers end within
// a piece of each other although the pieces differ in cost (a PR2 page cut into two halves by
// their images took 12.9 and 16.7 s of CPU), few enough that asking for one costs nothing. A joint
// section is never cut (PiecePageImages): its camera is fitted in one worker.
constexpr int kPiecesPerWorker = 8;

// The page as planned: the robot prepared as its pictures show it, its content and its files.
struct PagePlan {
  std::unique_ptr<request::RenderSession> session;   // holds the prepared robot's caches
  request::Prepared prepared;
  docs::PageLook look;
  docs::RobotPage page;
  std::vector<docs::PageImage> files;   // every picture and animation of the page
};

// Loads the robot and plans its page (GL-free).
PagePlan PlanPage(DocsOptions& o, const gl::BackendChoice& backend, Warnings& warnings) {
  request::RenderRequest& request = o.render.request;
  // the page's views are always fitted, each over what it shows (the docs stage does that)
  request.fit = true;
  request::ResolvedRequest resolved = request::ResolveRequest(request, request::CommandLineLabel, warnings);
  const render::Fit fit = std::exchange(resolved.settings.fit, render::Fit::kNone);
  PagePlan plan;
  plan.session = std::make_unique<request::RenderSession>(backend);
  plan.prepared = plan.session->Prepare(resolved, warnings);
  plan.look.backend = backend;
  plan.look.settings = plan.prepared.settings;
  plan.look.settings.fit = fit;
  plan.look.tf_scale_given = !request.tf_scale.empty();
  docs::PageOptions options;
  options.section_globs = o.section_globs;
  options.positions = plan.prepared.positions;
  options.posed = !request.joints.empty() || !request.joint_file.empty();
  options.view_size = {plan.look.settings.size.width, plan.look.settings.size.height};
  // the joints' pictures and animations three quarters of --size: large enough to see a joint
  // move, and a PR2's page of 39 joints within 5 MB as WebP
  options.joint_size = {std::max(1, options.view_size.width * 3 / 4), std::max(1, options.view_size.height * 3 / 4)};
  options.animation_extension = o.animations == "none" ? "" : "." + o.animations;
  options.still_extension = "." + o.stills;
  plan.page = docs::MakeRobotPage(*plan.prepared.robot, request.model.path, request.model.xacro_args, options, warnings);
  plan.files = docs::PageImages(plan.page, plan.look);
  return plan;
}

// A worker process of a parent's `docs --jobs N` (the hidden --worker-pieces and --worker-output,
// the parent's folder):
// the pictures and animations of each piece the parent hands it into the parent's folder, its
// progress on stdout, its warnings on stderr for the parent to gather; no documents.
void RunWorker(DocsOptions& o) {
  StopWhenParentEnds();
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);
  Warnings warnings;
  try {
    CheckOptions(o, warnings);
    o.render.ParseJointWords();
    o.render.request.model = o.model.ToRequest();
    const PagePlan plan = PlanPage(o, backend, warnings);
    const auto next = [&]() -> std::optional<std::vector<docs::PageImage>> {
      const std::optional<int> piece = NextPiece();
      if (!piece) return std::nullopt;
      return docs::PiecePageImages(plan.files, shard::CheckedShard(*piece, o.jobs.worker_pieces, "piece"));
    };
    docs::RenderPagePieces(plan.prepared.robot, plan.page, plan.look, next, o.jobs.worker_output, warnings,
                           [](std::int64_t done, std::int64_t) { ReportImagesDone(done); });
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarningsBeforeError(warnings);   // the parent gathers them (and applies --strict)
}

void Run(DocsOptions& o) {
  if (o.jobs.worker()) return RunWorker(o);
  if (o.output.empty() == o.check.empty()) {
    throw Error("docs: give -o DIR to write a page, or --check DIR to compare a committed page with a fresh one");
  }
  Warnings warnings;
  CheckOptions(o, warnings);
  o.render.ParseJointWords();
  request::RenderRequest& request = o.render.request;
  request.model = o.model.ToRequest();
  // the page replaces its folder as a whole: no file the page is made from may be in it
  OutputPlan outputs;
  if (!o.output.empty()) {
    request::AddRequestInputs(outputs, request);
    outputs.AddFolder(o.output, "-o");
    outputs.Prepare();
  } else if (std::error_code error; std::filesystem::exists(o.check, error) &&
                                    !std::filesystem::is_directory(o.check, error)) {
    throw Error("--check '" + o.check + "': exists and is not a folder");
  }
  const shard::ShardChoice choice =
      o.sharding.Choose(o.check.empty() ? "" : "docs --check compares the whole page with a fresh one");
  const int jobs = o.jobs.WorkerCount(choice.sharded());   // one process for a shard of a larger job
  const gl::BackendChoice backend = o.gl_options.Choice();
  // one process: Mesa loads while the model is read; workers load it themselves
  std::optional<std::future<void>> gl_loading;
  if (jobs == 1) gl_loading = gl::StartLoadingGl(backend.backend);
  // the page is made in a new folder, moved into place once complete (or a scratch folder for --check)
  std::optional<docs::PageFolder> page_folder;
  std::optional<docs::ScratchFolder> scratch_folder;
  const std::filesystem::path folder = o.check.empty() ? page_folder.emplace(o.output).path() : scratch_folder.emplace().path();
  try {
    // workers start before this process reads the model, which they read too
    std::optional<WorkerProcesses> workers;
    if (jobs > 1) {
      const int pieces = kPiecesPerWorker * jobs;
      workers.emplace(jobs, "docs", JobOptions::WorkerOptions(pieces, folder.string()), pieces);
    }
    PagePlan plan = PlanPage(o, backend, warnings);
    const std::vector<docs::PageImage> files = docs::ShardPageImages(plan.files, choice.shard);
    PrintShardLine(choice, files.size(), plan.files.size(), "pictures and animations",
                   std::to_string(docs::ImageCount(files)) + " of " + std::to_string(docs::ImageCount(plan.files)) +
                       " images, and the page's text");
    // a progress bar of pictures and animation frames on a terminal, a summary line anywhere
    stream::ProgressBar bar(docs::ImageCount(files), "images",
                            o.quiet ? stream::ProgressBar::Display::kNever
                                    : stream::ProgressBar::Display::kIfTerminal);
    if (workers) {
      const std::vector<docs::LeftOutName> tf_left_out = docs::TfLeftOut(plan.prepared.robot, plan.page, plan.look, warnings);
      plan.session.reset();   // its meshes and textures: the workers have their own
      workers->Wait([&](std::int64_t done) { bar.Update(done); }, warnings);
      docs::WritePageDocuments(plan.page, tf_left_out, folder);
    } else {
      docs::WritePage(plan.prepared.robot, plan.page, plan.look, files, folder, warnings,
                      [&](std::int64_t done, std::int64_t) { bar.Update(done); });
    }
    if (!o.check.empty()) {
      bar.Finish("made the page afresh to compare with " + o.check);
      PrintWarnings(warnings);
      if (!std::filesystem::is_directory(o.check)) {
        Report(o.check, {"no page here (" + std::string(docs::kHtmlFile) + " and the rest are missing)"});
      }
      Report(o.check, docs::ComparePages(o.check, folder));
      return;
    }
    PrintWarnings(warnings);
    page_folder->Commit();
    outputs.Commit();
    bar.Finish("wrote " + (std::filesystem::path(o.output) / docs::kHtmlFile).string() + " and " +
               (std::filesystem::path(o.output) / docs::kMarkdownFile).string());
  } catch (const CommandExit&) {
    throw;
  } catch (const StoppedBySignal&) {
    throw;
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
}

}  // namespace

void AddDocsCommand(CLI::App& app) {
  auto o = std::make_shared<DocsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "docs", "Write a robot's documentation page: pictures, joint by joint motion, tree and tables");
  o->model.AddOptions(*cmd);
  cmd->add_option("-o,--output", o->output,
                  "folder to write README.md, index.html and the images into (replaced as a whole; "
                  "it must be new, empty or a page of urdfsnap docs). With --shard K/N, a contiguous "
                  "run of the pictures and animations and the page's text: the shards' folders "
                  "copied into one are the page");
  cmd->add_option("--check", o->check,
                  "instead of writing, compare the page in this folder with a fresh one: exit 0 when "
                  "it is up to date, 1 when stale (images within the snapshot tolerances, text exactly)");
  cmd->add_option("--sections", o->section_globs,
                  "give sections only to the movable joints matching GLOB (* ? [..], repeatable; "
                  "default: every movable joint)");
  std::vector<std::string> formats;
  for (const std::string& extension : docs::AnimationExtensions()) formats.push_back(extension.substr(1));
  formats.push_back("none");
  o->animations = "webp";
  cmd->add_option("--animations", o->animations,
                  "format of the joint sweeps and the turntable: webp (lossy, about a quarter of gif's bytes), "
                  "gif or none (default webp)")
      ->check(CLI::IsMember(formats));
  cmd->add_option("--stills", o->stills,
                  "format of the pictures: webp (lossy, a third to an eighth of png's bytes) or png (lossless; default webp)")
      ->check(CLI::IsMember({"webp", "png"}));
  cmd->add_flag("-q,--quiet", o->quiet, "no progress bar (it is shown only on a terminal anyway)");
  o->sharding.AddOptions(*cmd, "pictures and animations of the page");
  o->render.AddOptions(*cmd, kNotOnDocs);
  for (const std::string_view name : kNotOnDocs) {
    const std::string option = request::CommandLineLabel(name);
    const auto given = [o, name] { o->refused.emplace_back(name); };
    if (name == "fit" || name == "distort") {
      cmd->add_flag_callback(option, given)->group("");
    } else {
      cmd->add_option_function<std::string>(option, [given](const std::string&) { given(); })->group("");
    }
  }
  o->gl_options.AddOptions(*cmd);
  o->jobs.AddOptions(*cmd, "make the page in N worker processes at once, each a shard of its pictures and "
                          "animations (default: one per core this process may use; 1: in this process). "
                          "With --shard, or a model or joint file on standard input, one process");
  cmd->callback([o] { RunStoppable([o] { Run(*o); }); });   // a signal ends it after the page's folder is removed
}

}  // namespace urdfsnap::cli
