// Parallel loading of a robot's mesh files (a worker per core pulling from one list).
#include "scene/mesh_prefetch.h"

#include <algorithm>
#include <atomic>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "common/error.h"
#include "geometry/mesh_file.h"
#include "geometry/mesh_uri.h"

namespace urdfsnap::scene {

namespace {

void AddMeshFile(const urdf::GeometrySharedPtr& geometry, const SceneOptions& options,
                 std::set<std::string>& files) {
  if (!geometry || geometry->type != urdf::Geometry::MESH) return;
  const auto& mesh = static_cast<const urdf::Mesh&>(*geometry);
  if (mesh.filename.empty()) return;
  try {
    files.insert(geometry::ResolveMeshUri(mesh.filename, options.model_file, options.packages));
  } catch (const Error&) {
    // not found: the scene builder reports it (or skips it with --allow-missing-meshes)
  }
}

}  // namespace

void PrefetchMeshFiles(const model::Robot& robot, const SceneOptions& options) {
  std::set<std::string> unique;
  for (const auto& link : robot.links()) {
    if (options.show_visual) {
      for (const auto& visual : link.urdf->visual_array) AddMeshFile(visual->geometry, options, unique);
    }
    if (options.show_collision) {
      for (const auto& collision : link.urdf->collision_array) {
        AddMeshFile(collision->geometry, options, unique);
      }
    }
  }
  if (unique.size() < 2) return;  // nothing to overlap
  const std::vector<std::string> files(unique.begin(), unique.end());
  std::atomic<size_t> next = 0;
  const size_t workers =
      std::min<size_t>(files.size(), std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::jthread> pool;
  for (size_t w = 0; w < workers; ++w) {
    pool.emplace_back([&] {
      for (size_t i = next++; i < files.size(); i = next++) {
        try {
          geometry::LoadMeshFile(files[i]);
        } catch (const Error&) {
          // a broken file: the scene builder loads it again and reports it with its link
        }
      }
    });
  }
}

}  // namespace urdfsnap::scene
