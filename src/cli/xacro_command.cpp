// `urdfsnap xacro FILE [NAME:=VALUE...] [-o OUT] [--inorder|-i] [--xacro-ns] [--deps]
// [--package PKG=DIR]`: a drop-in for ROS's xacro command, printing the expanded document (or the
// dependencies) as it does and exiting 2 on errors.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "cli/command.h"
#include "common/error.h"
#include "common/warnings.h"
#include "common/output_plan.h"
#include "xacro/xacro.h"

namespace urdfsnap::cli {
namespace {

struct XacroFlags {
  std::string file;
  std::vector<std::string> words;
  std::string output;
  std::vector<std::string> packages;
  bool inorder = false;
  bool xacro_ns = false;
  bool deps = false;
  bool quiet = false;
};

void Run(const XacroFlags& flags) {
  xacro::Options options;
  options.xacro_ns = flags.xacro_ns;
  for (const std::string& word : flags.words) {
    const size_t sep = word.find(":=");
    if (sep == std::string::npos) throw Error("xacro: unexpected argument '" + word + "' (expected NAME:=VALUE)");
    options.args.emplace_back(word.substr(0, sep), word.substr(sep + 2));
  }
  for (const std::string& p : flags.packages) {
    const size_t sep = p.find('=');
    if (sep == std::string::npos || sep == 0) throw Error("--package expects PKG=DIR, got '" + p + "'");
    options.packages[p.substr(0, sep)] = p.substr(sep + 1);
  }
  if (flags.inorder) {
    std::fprintf(stderr, "xacro: in-order processing became default in ROS Melodic. You can drop the option.\n");
  }
  Warnings warnings;
  xacro::Result result;
  try {
    result = xacro::ExpandFile(flags.file, options, warnings);
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarnings(warnings);
  std::string text;
  if (flags.deps) {
    for (const std::string& d : result.dependencies) text += (text.empty() ? "" : " ") + d;
  } else {
    text = result.xml;
  }
  if (flags.output.empty()) {
    WriteToStdout(text);
  } else {
    // never over a file it read; ROS's xacro creates the output's folder too
    OutputPlan outputs;
    outputs.AddInput(flags.file, "the xacro file");
    for (const std::string& file : result.dependencies) outputs.AddInput(file, "a file it includes");
    outputs.AddFile(flags.output, "-o");
    outputs.Prepare();
    outputs.Write(flags.output, text);
    outputs.Commit();
  }
}

}  // namespace

void AddXacroCommand(CLI::App& app) {
  auto flags = std::make_shared<XacroFlags>();
  auto* cmd = app.add_subcommand("xacro", "Expand a xacro file to URDF (a drop-in for ROS's xacro)");
  cmd->add_option("file", flags->file, "The xacro file")->required();
  cmd->add_option("args", flags->words, "NAME:=VALUE arguments");
  cmd->add_option("-o,--output", flags->output, "Write to this file instead of stdout");
  cmd->add_flag("-i,--inorder", flags->inorder, "Accepted for compatibility (in-order is the default)");
  cmd->add_flag("--xacro-ns", flags->xacro_ns,
                "Modern strict behaviour: tags without the xacro: prefix are never macro calls");
  cmd->add_flag("--deps", flags->deps, "Print the files the document depends on instead of the document");
  cmd->add_flag("-q", flags->quiet, "Accepted for compatibility");
  cmd->add_option("--package", flags->packages, "PKG=DIR: where $(find PKG) points (repeatable)")
      ->allow_extra_args(false);
  cmd->callback([flags] { Run(*flags); });
}

}  // namespace urdfsnap::cli
