// The options that describe one render on the command line, shared by `render` and `serve`
// (whose page starts from them): -j NAME=VALUE, --joints FILE and every view and display option
// of request::TextOptions/FlagOptions.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "request/render_request.h"

namespace urdfsnap::cli {

struct RenderOptions {
  std::vector<std::string> joint_words;  // NAME=VALUE, parsed by Apply
  request::RenderRequest request;        // everything else, filled by CLI11 directly

  // Adds -j, --joints and the view and display options to `command`, but those in `left_out`
  // (see AddViewOptions).
  void AddOptions(CLI::App& command, std::span<const std::string_view> left_out = {});
  // Parses the -j words into request.joints; throws urdfsnap::Error for a malformed one.
  void ParseJointWords();
};

}  // namespace urdfsnap::cli
