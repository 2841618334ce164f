// Loading the MODEL argument: file reading, xacro detection and expansion, URDF parsing.
#include "cli/model_source.h"

#include <fstream>
#include <sstream>

#include "common/error.h"
#include "xacro/xacro.h"

namespace urdfsnap::cli {

namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open the model file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Words that look like NAME:=VALUE are xacro arguments; anything else is a usage error.
std::vector<std::pair<std::string, std::string>> XacroArgs(const std::vector<std::string>& words) {
  std::vector<std::pair<std::string, std::string>> args;
  for (const auto& word : words) {
    const auto at = word.find(":=");
    if (at == std::string::npos || at == 0) {
      throw Error("unexpected argument '" + word + "' (xacro arguments are written NAME:=VALUE)");
    }
    args.emplace_back(word.substr(0, at), word.substr(at + 2));
  }
  return args;
}

}  // namespace

std::map<std::string, std::string> ParsePackageWords(const std::vector<std::string>& words) {
  std::map<std::string, std::string> packages;
  for (const auto& word : words) {
    const auto at = word.find('=');
    if (at == std::string::npos || at == 0) {
      throw Error("--package '" + word + "': expected PKG=DIR");
    }
    packages[word.substr(0, at)] = word.substr(at + 1);
  }
  return packages;
}

void ModelSource::AddOptions(CLI::App& command) {
  command.add_option("MODEL", path, "URDF or xacro file")->required();
  command.add_option("NAME:=VALUE", xacro_words, "xacro arguments, as for ROS's xacro");
  command.add_option("--package", packages,
                     "where $(find PKG) and package://PKG point (PKG=DIR, repeatable)");
  command.add_flag("--xacro-ns", xacro_ns,
                   "modern xacro's strict rule: only xacro:-prefixed tags are macro calls");
}

model::Robot ModelSource::Load(Warnings& warnings) const {
  const auto args = XacroArgs(xacro_words);
  const std::string text = ReadFile(path);
  const bool is_xacro = EndsWith(path, ".xacro") || !args.empty() ||
                        text.find("http://www.ros.org/wiki/xacro") != std::string::npos;
  if (!is_xacro) return model::LoadRobot(text, path, warnings);
  xacro::Options options;
  options.args = args;
  options.packages = ParsePackageWords(packages);
  options.xacro_ns = xacro_ns;
  // lines in URDF errors refer to the expanded document, not to the xacro source
  return model::LoadRobot(xacro::ExpandFile(path, options, warnings).xml, path + " (expanded)",
                          warnings);
}

}  // namespace urdfsnap::cli
