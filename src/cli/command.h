// What every subcommand file shares: how it registers itself with the CLI11 app and how it ends
// with an exit status other than 0 (urdfsnap::Error ends with status 2; see main.cpp).
#pragma once

#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "common/warnings.h"

namespace urdfsnap::cli {

// Thrown by a command's callback to end the process with `code` after printing nothing more
// (e.g. `diff` exits 1 when images differ).
struct CommandExit {
  int code;
};

// --strict, set by main.cpp while the command line is parsed (before any command runs).
bool& StrictWarnings();

// Prints each warning to stderr as "urdfsnap: warning: ...". Under --strict the last one is thrown
// as urdfsnap::Error instead (the others are printed first), so the command ends with status 2
// before it writes anything.
void PrintWarnings(const Warnings& warnings);

// Prints each warning as a warning whatever --strict says: for the warnings that led up to an
// error, which may explain it.
void PrintWarningsBeforeError(const Warnings& warnings);

// Writes `text` to stdout and flushes it; throws urdfsnap::Error when that fails (a closed pipe,
// a full disk).
void WriteToStdout(std::string_view text);

// A CLI11 check for a numeric option: the value must be a finite number ("nan", "inf" and
// "1e999" are refused with "expected a finite number, got 'nan'", which CLI11 prefixes with the
// option's name). CLI::Range alone lets NaN through: it compares false both ways.
CLI::Validator FiniteNumber();

// One line per snapshot case on stdout, flushed (CI logs show progress): "FAILED   NAME: MESSAGE";
// for a case that could not be rendered (word "ERROR") also "urdfsnap: error: MESSAGE" on stderr.
void PrintCaseLine(const char* word, const std::string& name, const std::string& message);

// Each subcommand file defines one of these; main.cpp calls them all.
void AddRenderCommand(CLI::App& app);
void AddAnimateCommand(CLI::App& app);
void AddDatasetCommand(CLI::App& app);
void AddInfoCommand(CLI::App& app);
void AddXacroCommand(CLI::App& app);
void AddDiffCommand(CLI::App& app);
void AddSnapshotCommand(CLI::App& app);
void AddServeCommand(CLI::App& app);
void AddDocsCommand(CLI::App& app);
// `snapshot merge`, added to the snapshot command by AddSnapshotCommand.
void AddSnapshotMergeCommand(CLI::App& snapshot);

}  // namespace urdfsnap::cli
