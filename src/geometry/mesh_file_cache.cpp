// LoadMeshFile: a process-wide cache of mesh files, read by the mesh module (mesh_module.h).
#include "geometry/mesh_file.h"

#include <filesystem>
#include <system_error>
#include <tuple>

#include "common/error.h"
#include "common/module_loader.h"
#include "common/shared_cache.h"
#include "geometry/internal/mesh_module.h"

namespace urdfsnap::geometry {

namespace fs = std::filesystem;

std::shared_ptr<const MeshFile> LoadMeshFile(const std::string& path) {
  std::error_code ec;
  const fs::path canonical = fs::canonical(path, ec);
  if (ec) throw Error(SourceLocation{path}, "cannot read mesh file: " + ec.message());
  // keyed by the file's identity and version, so an edited file is read again
  const auto modified = fs::last_write_time(canonical, ec).time_since_epoch().count();
  const auto size = fs::file_size(canonical, ec);
  static SharedCache<std::tuple<std::string, long long, std::uintmax_t>, MeshFile> cache;
  return cache.Get({canonical.string(), static_cast<long long>(modified), ec ? 0 : size}, [&] {
    const MeshModule* module = nullptr;
    try {
      module = &LoadModule<MeshModule>(URDFSNAP_MESH_MODULE, kMeshModuleEntry,
                                       "the mesh file reader (assimp)");
    } catch (const Error& e) {
      throw Error(SourceLocation{path}, e.what());
    }
    return std::make_shared<const MeshFile>(module->read_mesh_file(canonical));
  });
}

}  // namespace urdfsnap::geometry
