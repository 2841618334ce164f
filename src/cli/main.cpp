// urdfsnap's entry point: builds the CLI11 app from the subcommand files and maps failures to exit
// statuses: 0 success, 2 bad input or usage ("urdfsnap: error: ..."), or a command's CommandExit.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "cli/command.h"
#include "common/did_you_mean.h"
#include "common/error.h"
#include "common/version.h"
#include "gl/gl_context.h"

namespace {

// The message for a command line whose command is missing or unknown ("urdfsnap frobnicate",
// "urdfsnap snapshot frob"), or "" when the parse error is another one. CLI11 only says "A
// subcommand is required" there.
std::string CommandError(const CLI::App& app) {
  // the deepest command given, which wants one of its own
  const CLI::App* level = &app;
  while (!level->get_subcommands().empty()) level = level->get_subcommands().front();
  if (level->get_require_subcommand_min() == 0) return "";
  std::vector<std::string> names;
  for (const CLI::App* sub : level->get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  const std::string kind = level == &app ? "command" : level->get_name() + " command";
  // what was not understood (words fall through from a command to the top, where --strict is)
  std::string word, option;
  for (const std::string& arg : app.remaining(true)) {
    std::string& slot = arg.rfind("-", 0) == 0 ? option : word;
    if (slot.empty()) slot = arg;
  }
  if (word.empty() && !option.empty()) {
    return "unknown option '" + option + "' and no " + kind + " (commands: " + list + ")";
  }
  if (word.empty()) return "no " + kind + " given (commands: " + list + "; see 'urdfsnap --help')";
  return "unknown " + kind + " '" + word + "' (" + urdfsnap::DidYouMean(word, names) + "commands: " + list + ")";
}

// The message for an option the command does not have ("urdfsnap render m.urdf --yaww 1"), with the
// nearest of its options, or "" when the parse error is another one.
std::string OptionError(const CLI::App& app) {
  const CLI::App* level = &app;
  while (!level->get_subcommands().empty()) level = level->get_subcommands().front();
  if (level == &app) return "";
  std::string unknown;
  for (const std::string& arg : app.remaining(true)) {
    if (arg.size() > 1 && arg[0] == '-' && unknown.empty()) unknown = arg.substr(0, arg.find('='));
  }
  if (unknown.empty()) return "";
  std::vector<std::string> names;
  for (const CLI::Option* option : level->get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  names.push_back("--strict");
  const std::string command = level->get_parent() == &app ? level->get_name()
                                                          : level->get_parent()->get_name() + " " + level->get_name();
  return "unknown option '" + unknown + "' for " + command + " (" + urdfsnap::DidYouMean(unknown, names) +
         "see 'urdfsnap " + command + " --help')";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"urdfsnap: RViz-like PNG images of URDF/xacro robots, headless", "urdfsnap"};
  app.require_subcommand(1);
  // --version alone is the version string (a few milliseconds); with --verbose also the GL lines,
  // which make a context to say what it is (Mesa loads). The version flag ends the parse where it
  // stands, so --verbose is looked for among all the words.
  const bool verbose = std::find(argv + 1, argv + argc, std::string_view("--verbose")) != argv + argc;
  app.set_version_flag("--version", [verbose] {
    const std::string version = "urdfsnap " + std::string(urdfsnap::Version());
    return verbose ? version + "\n" + urdfsnap::gl::DescribeGlBackends() : version;
  }, "print the version and exit; with --verbose also the GL backends compiled in and the one used here");
  bool verbose_flag = false;  // read from the words above: the flag is only accepted here
  app.add_flag("--verbose", verbose_flag,
               "with --version: also the GL backends compiled in and the one used here");
  app.add_flag("--strict", urdfsnap::cli::StrictWarnings(),
               "treat warnings as errors: print the warning as an error, write nothing, exit 2 "
               "(before or after the command)");
  // options the subcommands do not know (--strict) are passed on to this level
  app.fallthrough();
  urdfsnap::cli::AddRenderCommand(app);
  urdfsnap::cli::AddAnimateCommand(app);
  urdfsnap::cli::AddDatasetCommand(app);
  urdfsnap::cli::AddInfoCommand(app);
  urdfsnap::cli::AddXacroCommand(app);
  urdfsnap::cli::AddDiffCommand(app);
  urdfsnap::cli::AddSnapshotCommand(app);
  urdfsnap::cli::AddServeCommand(app);
  urdfsnap::cli::AddDocsCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string command_error = CommandError(app);
    if (command_error.empty()) command_error = OptionError(app);
    if (!command_error.empty()) {
      std::fprintf(stderr, "urdfsnap: error: %s\n", command_error.c_str());
    } else {
      std::fprintf(stderr, "urdfsnap: error: %s (see 'urdfsnap --help')\n", e.what());
    }
    return 2;
  } catch (const urdfsnap::cli::CommandExit& e) {
    return e.code;
  } catch (const urdfsnap::Error& e) {
    std::fprintf(stderr, "urdfsnap: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "urdfsnap: error: out of memory\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "urdfsnap: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
