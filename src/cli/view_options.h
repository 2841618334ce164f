// render's view and display options (request::TextOptions/FlagOptions) on a subcommand that
// renders: `render`, `serve` (through RenderOptions) and `docs` register the same table.
#pragma once

#include <span>
#include <string_view>

#include <CLI/CLI.hpp>

#include "request/render_request.h"

namespace urdfsnap::cli {

// Adds "--NAME VALUE" for each text option and "--NAME" for each flag, filling `request`, except
// the options named in `left_out` (ones that cannot work on `command`; it says so itself).
void AddViewOptions(CLI::App& command, request::RenderRequest& request,
                    std::span<const std::string_view> left_out = {});

}  // namespace urdfsnap::cli
