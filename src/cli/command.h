// What every subcommand file shares: how it registers itself with the CLI11 app and how it ends
// with an exit status other than 0 (urdfsnap::Error ends with status 2; see main.cpp).
#pragma once

#include <CLI/CLI.hpp>

#include "common/warnings.h"

namespace urdfsnap::cli {

// Thrown by a command's callback to end the process with `code` after printing nothing more
// (e.g. `diff` exits 1 when images differ).
struct CommandExit {
  int code;
};

// Prints each warning to stderr as "urdfsnap: warning: ...".
void PrintWarnings(const Warnings& warnings);

// Each subcommand file defines one of these; main.cpp calls them all.
void AddRenderCommand(CLI::App& app);
void AddInfoCommand(CLI::App& app);
void AddXacroCommand(CLI::App& app);
void AddDiffCommand(CLI::App& app);
void AddSnapshotCommand(CLI::App& app);

}  // namespace urdfsnap::cli
