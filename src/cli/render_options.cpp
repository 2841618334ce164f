// Registering render's option table with CLI11.
#include "cli/render_options.h"

namespace urdfsnap::cli {

void RenderOptions::AddOptions(CLI::App& command) {
  command.add_option("-j,--joint", joint_words, "joint value NAME=VALUE in rad or m (repeatable)");
  command.add_option("--joints", request.joint_file,
                     "YAML/JSON joint file: {name: value} or {name: [...], position: [...]}");
  for (const request::TextOption& option : request::TextOptions()) {
    command.add_option("--" + std::string(option.name), request.*option.field, option.help);
  }
  for (const request::FlagOption& option : request::FlagOptions()) {
    command.add_flag("--" + std::string(option.name), request.*option.field, option.help);
  }
}

void RenderOptions::ParseJointWords() {
  for (const auto& word : joint_words) model::ParseJointAssignment(word, request.joints);
}

}  // namespace urdfsnap::cli
