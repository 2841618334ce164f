// Loading a robot's mesh files on all cores at once (a worker per core pulling from one list):
// the slow part of preparing a mesh-heavy robot.
#pragma once

#include <exception>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "geometry/mesh_file.h"

namespace urdfsnap::geometry {

// What loading one file gave: the file, or the exception LoadMeshFile threw.
struct MeshLoad {
  std::shared_ptr<const geometry::MeshFile> file;
  std::exception_ptr error;
};

// Loads every file of `paths` (resolved file names) with LoadMeshFile, in parallel.
std::map<std::string, MeshLoad> LoadMeshFiles(const std::set<std::string>& paths);

}  // namespace urdfsnap::geometry
