// Loading a ModelRequest: file reading, xacro detection and expansion, URDF parsing.
#include "request/model_request.h"

#include "common/error.h"
#include "common/file_reading.h"
#include "xacro/xacro.h"

namespace urdfsnap::request {

namespace {

std::string ReadFile(const std::string& path) {
  try {
    return ReadFileBounded(path);
  } catch (const FileReadError& e) {
    throw Error(SourceLocation{path}, std::string("cannot read the model file: ") + e.what());
  }
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

LoadedModel LoadModel(const ModelRequest& request, Warnings& warnings) {
  const std::string text = ReadFile(request.path);
  const bool is_xacro = EndsWith(request.path, ".xacro") || !request.xacro_args.empty() ||
                        text.find("http://www.ros.org/wiki/xacro") != std::string::npos;
  if (!is_xacro) {
    return {std::make_shared<const model::Robot>(model::LoadRobot(text, request.path, warnings)), {request.path}};
  }
  xacro::Options options;
  options.args = request.xacro_args;
  options.packages = request.packages;
  options.xacro_ns = request.xacro_ns;
  xacro::Result expanded = xacro::ExpandFile(request.path, options, warnings);
  LoadedModel loaded;
  loaded.files.push_back(request.path);
  loaded.files.insert(loaded.files.end(), expanded.dependencies.begin(), expanded.dependencies.end());
  // lines in URDF errors refer to the expanded document, not to the xacro source
  loaded.robot = std::make_shared<const model::Robot>(
      model::LoadRobot(expanded.xml, request.path + " (expanded)", warnings));
  return loaded;
}

}  // namespace urdfsnap::request
