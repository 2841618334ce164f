// What every subcommand file shares: how it registers itself with the CLI11 app and how it ends
// with an exit status other than 0 (urdfsnap::Error ends with status 2; see main.cpp).
#pragma once

#include <CLI/CLI.hpp>

namespace urdfsnap::cli {

// Thrown by a command's callback to end the process with `code` after printing nothing more
// (e.g. `diff` exits 1 when images differ).
struct CommandExit {
  int code;
};

// Each subcommand file defines one of these; main.cpp calls them all.
void AddXacroCommand(CLI::App& app);

}  // namespace urdfsnap::cli
