// AddViewOptions: one CLI11 option per row of the request's option table.
#include "cli/view_options.h"

namespace urdfsnap::cli {

void AddViewOptions(CLI::App& command, request::RenderRequest& request) {
  for (const request::TextOption& option : request::TextOptions()) {
    command.add_option("--" + std::string(option.name), request.*option.field, option.help);
  }
  for (const request::FlagOption& option : request::FlagOptions()) {
    command.add_flag("--" + std::string(option.name), request.*option.field, option.help);
  }
}

}  // namespace urdfsnap::cli
