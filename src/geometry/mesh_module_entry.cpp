// urdfsnap-meshes.so's entry point: its table (the assimp reader), for its own build only.
#include "common/module_loader.h"
#include "geometry/internal/mesh_module.h"

// kMeshModuleEntry
extern "C" __attribute__((visibility("default"))) const void* urdfsnap_mesh_module(
    const char* version) {
  static const urdfsnap::geometry::MeshModule table{&urdfsnap::geometry::ReadMeshFile};
  return urdfsnap::IsOwnVersion(version) ? &table : nullptr;
}
