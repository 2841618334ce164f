// Mesh files (STL, COLLADA, OBJ and whatever else assimp reads) loaded the way RViz 1.14 loads them
// in src/rviz/mesh_loader.cpp: the same assimp post-processing, the same node transforms and unit
// scale, and the material rules of src/rviz/robot/robot_link.cpp reduced to "takes the URDF
// material" or "keeps the file's diffuse colour, emission and texture units". Pure geometry: no
// GL, no URDF.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry {

// One sub-mesh of a file: one assimp mesh as placed by one node of the file's node tree.
struct MeshPart {
  // Positions in metres of the mesh frame (node transforms applied, the root node's without its
  // rotation as RViz does, which honours a COLLADA unit and ignores its up axis); normals as in
  // the file, else flat ones generated from the winding.
  TriangleMesh mesh;
  // True where RViz gives the sub-mesh the link's URDF material (STL files, whose sub-meshes get
  // Ogre's BaseWhiteNoLighting); false where the file's own material is kept.
  bool takes_urdf_material = false;
  // The file's diffuse colour; assimp's default material for a file without any is 0.6 grey.
  // Alpha is always 1: RViz's mesh_loader.cpp looks for the opacity under a key assimp never uses.
  // Meaningless when takes_urdf_material.
  Eigen::Vector4f diffuse{1, 1, 1, 1};
  // The file's emissive colour, which RViz adds as the material's self-illumination (usually 0).
  // Meaningless when takes_urdf_material.
  Eigen::Vector3f emissive{0, 0, 0};
  // RViz's texture units: one per texture map the material names, of whatever kind (diffuse,
  // normal or bump, height, specular, emissive, base colour...), and each of them shows the
  // material's *diffuse* map, so the lit colour is multiplied by that map once per map (a diffuse
  // and a bump map give colour x t^2). 0 for a material without maps. Meaningless when
  // takes_urdf_material.
  int texture_units = 0;
  // The image the texture units show: the diffuse map's name joined to the mesh file's folder, as
  // RViz joins them ("Assume textures are in paths relative to the mesh"). Empty when the material
  // has maps but none of them a diffuse map in a file (no diffuse map, or an embedded "*N" one):
  // RViz's units then name an image that cannot be loaded, and Ogre draws its warning texture.
  // The file is not opened here.
  std::string texture;
};

struct MeshFile {
  std::vector<MeshPart> parts;
  std::size_t triangle_count = 0;  // over all parts
};

// Largest file LoadMeshFile reads, and most triangles it accepts from one file.
inline constexpr std::size_t kMaxMeshFileBytes = std::size_t{512} << 20;
inline constexpr std::size_t kMaxMeshTriangles = 20'000'000;

// Loads the mesh file at `path` (a file system path, see mesh_uri.h for URIs) as RViz does. While
// the returned object is held anywhere, later calls naming the same file (canonical path, same
// modification time and size) return it instead of reading the file again; an edited file is read
// anew. Thread-safe (common/shared_cache.h). Vertex colours are ignored; the first set of texture
// coordinates is kept (flipped so that v = 0 is the image's top, as RViz imports them). Throws
// urdfsnap::Error "PATH: ..." when the file is missing, unreadable, not a mesh assimp can read,
// holds no triangles, is larger than kMaxMeshFileBytes or has more than kMaxMeshTriangles
// triangles.
std::shared_ptr<const MeshFile> LoadMeshFile(const std::string& path);

}  // namespace urdfsnap::geometry
