// AddViewOptions: one CLI11 option per row of the request's option table.
#include "cli/view_options.h"

#include <algorithm>

namespace urdfsnap::cli {

void AddViewOptions(CLI::App& command, request::RenderRequest& request,
                    std::span<const std::string_view> left_out) {
  const auto kept = [&](const char* name) { return std::find(left_out.begin(), left_out.end(), name) == left_out.end(); };
  for (const request::TextOption& option : request::TextOptions()) {
    if (kept(option.name)) command.add_option("--" + std::string(option.name), request.*option.field, option.help);
  }
  for (const request::FlagOption& option : request::FlagOptions()) {
    if (kept(option.name)) command.add_flag("--" + std::string(option.name), request.*option.field, option.help);
  }
}

}  // namespace urdfsnap::cli
