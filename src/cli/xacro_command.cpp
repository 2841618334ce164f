// `urdfsnap xacro`: placeholder until the xacro processor lands (issue 3).
#include "cli/command.h"
#include "common/error.h"

namespace urdfsnap::cli {

void AddXacroCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("xacro", "Expand a xacro file to URDF");
  cmd->allow_extras();
  cmd->callback([] { throw Error("xacro: not implemented yet"); });
}

}  // namespace urdfsnap::cli
