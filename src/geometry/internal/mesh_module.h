// The mesh module, urdfsnap-meshes.so (common/module_loader.h): mesh files read through assimp,
// loaded when a model first names a mesh file, so that commands and robots without meshes never
// load assimp (with draco and minizip behind it, ~2 ms of every start-up linking it).
#pragma once

#include <filesystem>

#include "geometry/mesh_file.h"

namespace urdfsnap::geometry {

// the module's entry point (mesh_module_entry.cpp)
inline constexpr char kMeshModuleEntry[] = "urdfsnap_mesh_module";

struct MeshModule {
  MeshFile (*read_mesh_file)(const std::filesystem::path& path);
};

// Inside the module: LoadMeshFile's reading, without its cache. Throws urdfsnap::Error "PATH: ..."
// as LoadMeshFile does.
MeshFile ReadMeshFile(const std::filesystem::path& path);

}  // namespace urdfsnap::geometry
