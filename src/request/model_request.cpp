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

model::Robot LoadModel(const ModelRequest& request, Warnings& warnings) {
  const std::string text = ReadFile(request.path);
  const bool is_xacro = EndsWith(request.path, ".xacro") || !request.xacro_args.empty() ||
                        text.find("http://www.ros.org/wiki/xacro") != std::string::npos;
  if (!is_xacro) return model::LoadRobot(text, request.path, warnings);
  xacro::Options options;
  options.args = request.xacro_args;
  options.packages = request.packages;
  options.xacro_ns = request.xacro_ns;
  // lines in URDF errors refer to the expanded document, not to the xacro source
  return model::LoadRobot(xacro::ExpandFile(request.path, options, warnings).xml,
                          request.path + " (expanded)", warnings);
}

}  // namespace urdfsnap::request
