// RenderWords: the view's numbers and the joint values as render's options, checked against
// model::ResolveJointPositions so that mimic joints are named only when they must be.
#include "animation/frame_reproduction.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "common/number_text.h"
#include "model/joint_values.h"

namespace urdfsnap::animation {

namespace {

// `word` quoted for a POSIX shell unless it is made only of characters no shell treats specially.
std::string ShellWord(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("_-+=.,:/@%").find(c) != std::string_view::npos;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::vector<std::string> RenderWords(const model::Robot& robot, const std::vector<double>& positions,
                                     const scene::OrbitView& view, bool clamp) {
  // '=' joins option and value, so that a negative number is never read as an option
  std::vector<std::string> words = {
      "--yaw=" + FormatNumber(view.yaw), "--pitch=" + FormatNumber(view.pitch),
      "--distance=" + FormatNumber(view.distance),
      "--focal=" + FormatNumber(view.focal.x()) + "," + FormatNumber(view.focal.y()) + "," +
          FormatNumber(view.focal.z())};
  const auto& joints = robot.joints();
  model::NamedValues values;
  bool outside_limits = false;  // a trajectory drawn as recorded: render must not clamp it
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].IsMovable() && joints[i].mimic_leader < 0) values.emplace_back(joints[i].name, positions[i]);
    outside_limits = outside_limits || (joints[i].has_limits && (positions[i] < joints[i].lower ||
                                                                 positions[i] > joints[i].upper));
  }
  if (clamp && outside_limits) {
    words.push_back("--no-clamp");
    clamp = false;
  }
  // mimic joints whose position is not their leader's rule (the trajectory named them)
  Warnings ignored;
  const std::vector<double> resolved = model::ResolveJointPositions(robot, values, clamp, ignored);
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].mimic_leader >= 0 && resolved[i] != positions[i]) values.emplace_back(joints[i].name, positions[i]);
  }
  for (const auto& [name, value] : values) {
    words.push_back("-j");
    words.push_back(ShellWord(name + "=" + FormatNumber(value)));
  }
  return words;
}

std::string JoinWords(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + word;
  return line;
}

}  // namespace urdfsnap::animation
