// urdfsnap's entry point: builds the CLI11 app from the subcommand files and maps failures to exit
// statuses: 0 success, 2 bad input or usage ("urdfsnap: error: ..."), or a command's CommandExit.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli/command.h"
#include "common/error.h"
#include "common/version.h"
#include "gl/gl_context.h"

namespace {

// Levenshtein distance, for "did you mean"
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

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
  std::string hint;
  for (const std::string& name : names) {
    if (EditDistance(word, name) <= 2) hint = "did you mean '" + name + "'? ";
  }
  return "unknown " + kind + " '" + word + "' (" + hint + "commands: " + list + ")";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"urdfsnap: RViz-like PNG images of URDF/xacro robots, headless", "urdfsnap"};
  app.require_subcommand(1);
  // the GL lines make a context to say what it is (about 0.1 s: Mesa loads), hence a function
  app.set_version_flag("--version", [] { return "urdfsnap " + std::string(urdfsnap::Version()) + "\n" + urdfsnap::gl::DescribeGlBackends(); },
                       "print the version, the GL backends compiled in and the one used here, and exit");
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
    const std::string command_error = CommandError(app);
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
