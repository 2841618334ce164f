// FrameSource on today's request::RenderSession, and the list of a model's files worked out here
// until the render core can report the files it read (a session method the lead plans).
#include "serve/frame_source.h"

#include <set>

#include "common/error.h"
#include "geometry/mesh_file.h"
#include "geometry/mesh_uri.h"
#include "image/png_writer.h"
#include "request/render_session.h"
#include "xacro/xacro.h"

namespace urdfsnap::serve {

namespace {

// The file `uri` (a mesh or texture URI) names, or "" when it cannot be found now.
std::string FileOf(const std::string& uri, const request::ModelRequest& request) {
  if (uri.empty()) return "";
  try {
    return geometry::ResolveMeshUri(uri, request.path, request.packages);
  } catch (const Error&) {
    return "";  // the render reports it; the model is loaded again at the next edit or retry
  }
}

// Mesh files and the textures of URDF materials and of mesh materials.
void AddGeometryFiles(const model::Robot& robot, const request::ModelRequest& request,
                      std::set<std::string>& files) {
  const auto add_material = [&](const urdf::MaterialSharedPtr& material) {
    if (material) files.insert(FileOf(material->texture_filename, request));
  };
  const auto add_geometry = [&](const urdf::GeometrySharedPtr& geometry) {
    if (!geometry || geometry->type != urdf::Geometry::MESH) return;
    const std::string mesh = FileOf(static_cast<const urdf::Mesh&>(*geometry).filename, request);
    if (mesh.empty()) return;
    files.insert(mesh);
    try {
      for (const auto& part : geometry::LoadMeshFile(mesh)->parts) files.insert(part.texture);
    } catch (const Error&) {
      // a broken mesh: the render reports it
    }
  };
  for (const auto& [name, material] : robot.urdf().materials_) add_material(material);
  for (const auto& link : robot.links()) {
    for (const auto& visual : link.urdf->visual_array) {
      add_geometry(visual->geometry);
      add_material(visual->material);
    }
    for (const auto& collision : link.urdf->collision_array) add_geometry(collision->geometry);
  }
}

}  // namespace

FrameSource::FrameSource() : session_(std::make_unique<request::RenderSession>()) {}
FrameSource::~FrameSource() = default;

std::string FrameSource::RenderPng(const request::RenderRequest& request, Warnings& warnings) {
  const image::Image frame = session_->Render(
      request, [](std::string_view name) { return "--" + std::string(name); }, warnings);
  const std::vector<std::uint8_t> png = image::EncodePng(frame);
  return {png.begin(), png.end()};
}

void FrameSource::ForgetModels() {
  // today's session keeps models for its lifetime: a new session loads them again
  session_ = std::make_unique<request::RenderSession>();
}

WatchedModel LoadWatchedModel(const request::ModelRequest& request) {
  Warnings warnings;
  model::Robot robot = request::LoadModel(request, warnings);
  std::set<std::string> files{request.path};
  // LoadModel names an expanded xacro document "PATH (expanded)"; expanding it again (a few
  // milliseconds) is how its includes and YAML files are found until the core reports them
  if (robot.source() != request.path) {
    xacro::Options options;
    options.args = request.xacro_args;
    options.packages = request.packages;
    options.xacro_ns = request.xacro_ns;
    Warnings again;
    for (auto& file : xacro::ExpandFile(request.path, options, again).dependencies) {
      files.insert(std::move(file));
    }
  }
  AddGeometryFiles(robot, request, files);
  files.erase("");
  return {std::move(robot), std::move(warnings), {files.begin(), files.end()}};
}

}  // namespace urdfsnap::serve
