// Registering render's option table with CLI11.
#include "cli/render_options.h"

#include "cli/view_options.h"

namespace urdfsnap::cli {

void RenderOptions::AddOptions(CLI::App& command, std::span<const std::string_view> left_out) {
  command.add_option("-j,--joint", joint_words, "joint value NAME=VALUE in rad or m (repeatable)");
  command.add_option("--joints", request.joint_file,
                     "YAML/JSON joint file: {name: value} or {name: [...], position: [...]}");
  AddViewOptions(command, request, left_out);
}

void RenderOptions::ParseJointWords() {
  for (const auto& word : joint_words) model::ParseJointAssignment(word, request.joints);
}

}  // namespace urdfsnap::cli
