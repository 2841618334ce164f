// render's view and display options (request::TextOptions/FlagOptions) on a subcommand that
// renders: `render`, `serve` (through RenderOptions) and `docs` register the same table.
#pragma once

#include <CLI/CLI.hpp>

#include "request/render_request.h"

namespace urdfsnap::cli {

// Adds "--NAME VALUE" for each text option and "--NAME" for each flag, filling `request`.
void AddViewOptions(CLI::App& command, request::RenderRequest& request);

}  // namespace urdfsnap::cli
