// urdfsnap's entry point: builds the CLI11 app from the subcommand files and maps failures to exit
// statuses: 0 success, 2 bad input or usage ("urdfsnap: error: ..."), or a command's CommandExit.
#include <cstdio>
#include <exception>
#include <new>

#include "cli/command.h"
#include "common/error.h"

int main(int argc, char** argv) {
  CLI::App app{"urdfsnap: RViz-like PNG images of URDF/xacro robots, headless", "urdfsnap"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "urdfsnap 0.1.0");
  app.add_flag("--strict", urdfsnap::cli::StrictWarnings(),
               "treat warnings as errors: print the warning as an error, write nothing, exit 2 "
               "(before or after the command)");
  // options the subcommands do not know (--strict) are passed on to this level
  app.fallthrough();
  urdfsnap::cli::AddRenderCommand(app);
  urdfsnap::cli::AddAnimateCommand(app);
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
    std::fprintf(stderr, "urdfsnap: error: %s (see 'urdfsnap --help')\n", e.what());
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
