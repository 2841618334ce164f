// `urdfsnap docs`: a robot's documentation page (README.md, index.html and their pictures) written
// into a folder that appears only when complete, or `--check`ed against a fresh one for CI.
#include <filesystem>
#include <memory>

#include "cli/command.h"
#include "cli/gl_options.h"
#include "cli/model_source.h"
#include "cli/shard_options.h"
#include "cli/view_options.h"
#include "common/error.h"
#include "docs/animation_output.h"
#include "docs/page_check.h"
#include "docs/page_folder.h"
#include "docs/page_shard.h"
#include "docs/page_writer.h"
#include "gl/gl_context.h"
#include "request/model_request.h"
#include "request/render_request.h"
#include "request/settings_parsing.h"
#include "stream/progress_bar.h"

namespace urdfsnap::cli {

namespace {

struct DocsOptions {
  ModelSource model;
  std::string output, check;
  std::vector<std::string> joint_globs;
  std::string animations;
  bool quiet = false;
  ShardOptions sharding;            // a contiguous part of the page's pictures and animations
  request::RenderRequest request;   // the view and display options, filled by CLI11 directly
  GlOptions gl_options;
};

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

void Run(DocsOptions& o) {
  const gl::BackendChoice backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(backend.backend);   // overlaps loading Mesa with reading the model
  if (o.output.empty() == o.check.empty()) {
    throw Error("docs: give -o DIR to write a page, or --check DIR to compare a committed page with a fresh one");
  }
  o.request.model = o.model.ToRequest();
  const shard::ShardChoice choice =
      o.sharding.Choose(o.check.empty() ? "" : "docs --check compares the whole page with a fresh one");
  Warnings warnings;
  try {
    const request::LoadedModel loaded = request::LoadModel(o.request.model, warnings);
    docs::PageLook look;
    look.backend = backend;
    look.settings = request::ParseRenderSettings(
        o.request, [](std::string_view name) { return "--" + std::string(name); }, warnings);
    docs::PageOptions options;
    options.joint_globs = o.joint_globs;
    options.view_size = {look.settings.size.width, look.settings.size.height};
    options.joint_size = {std::max(1, options.view_size.width / 2), std::max(1, options.view_size.height / 2)};
    options.animation_extension = o.animations == "none" ? "" : "." + o.animations;
    const docs::RobotPage page = docs::MakeRobotPage(*loaded.robot, o.request.model.path,
                                                     o.request.model.xacro_args, options, warnings);
    const std::vector<docs::PageImage> all = docs::PageImages(page, look);
    const std::vector<docs::PageImage> files = docs::ShardPageImages(all, choice.shard);
    PrintShardLine(choice, files.size(), all.size(), "pictures and animations",
                   std::to_string(docs::ImageCount(files)) + " of " + std::to_string(docs::ImageCount(all)) +
                       " images, and the page's text");
    // a progress bar of pictures and animation frames on a terminal, a summary line anywhere
    stream::ProgressBar bar(docs::ImageCount(files), "images",
                            o.quiet ? stream::ProgressBar::Display::kNever
                                    : stream::ProgressBar::Display::kIfTerminal);
    const docs::Progress progress = [&](std::int64_t done, std::int64_t) { bar.Update(done); };
    if (!o.check.empty()) {
      const docs::ScratchFolder fresh;
      docs::WritePage(loaded.robot, page, look, files, fresh.path(), warnings, progress);
      bar.Finish("made the page afresh to compare with " + o.check);
      PrintWarnings(warnings);
      if (!std::filesystem::is_directory(o.check)) {
        Report(o.check, {"no page here (" + std::string(docs::kHtmlFile) + " and the rest are missing)"});
      }
      Report(o.check, docs::ComparePages(o.check, fresh.path()));
      return;
    }
    docs::PageFolder folder(o.output);
    docs::WritePage(loaded.robot, page, look, files, folder.path(), warnings, progress);
    PrintWarnings(warnings);
    folder.Commit();
    bar.Finish("wrote " + (std::filesystem::path(o.output) / docs::kHtmlFile).string() + " and " +
               (std::filesystem::path(o.output) / docs::kMarkdownFile).string());
  } catch (const CommandExit&) {
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
  cmd->add_option("--joints", o->joint_globs,
                  "give sections only to the movable joints matching GLOB (* ? [..], repeatable; "
                  "default: every movable joint)");
  std::vector<std::string> formats;
  for (const std::string& extension : docs::AnimationExtensions()) formats.push_back(extension.substr(1));
  formats.push_back("none");
  o->animations = formats.front();
  cmd->add_option("--animations", o->animations,
                  "format of the joint sweeps and the turntable (default " + formats.front() + ")")
      ->check(CLI::IsMember(formats));
  cmd->add_flag("-q,--quiet", o->quiet, "no progress bar (it is shown only on a terminal anyway)");
  o->sharding.AddOptions(*cmd, "pictures and animations of the page");
  AddViewOptions(*cmd, o->request);
  o->gl_options.AddOptions(*cmd);
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
