// ReadMeshFile (in urdfsnap-meshes.so): mesh file loading through assimp, following RViz 1.14's
// src/rviz/mesh_loader.cpp step by step.
#include "geometry/internal/mesh_module.h"

#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/LU>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "common/error.h"

namespace urdfsnap::geometry {

namespace fs = std::filesystem;

namespace {

// loadMeshFromResource() in mesh_loader.cpp: exactly these post-processing steps. FindInvalidData
// drops normals that are all zero (or all equal), and GenNormals then builds flat normals from the
// winding only where a mesh has none, so STL files render faceted; no JoinIdenticalVertices and
// no smoothing.
constexpr unsigned kRvizImportFlags = aiProcess_SortByPType | aiProcess_FindInvalidData |
                                      aiProcess_GenNormals | aiProcess_Triangulate |
                                      aiProcess_GenUVCoords | aiProcess_FlipUVs;

// loadMaterials() in mesh_loader.cpp picks materials by the file's extension: ".stl" and ".stlb"
// (any case) get Ogre's BaseWhiteNoLighting, which robot_link.cpp replaces by the link's material.
bool IsStlFile(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".stl" || ext == ".stlb";
}

// loadMaterials() in mesh_loader.cpp: the diffuse colour starts white and "$clr.diffuse" sets it
// with alpha 1. RViz's branch for opacity compares the key with "$clr.opacity", but assimp stores
// opacity as "$mat.opacity" (AI_MATKEY_OPACITY), so the branch never runs: every mesh material is
// opaque in RViz 1.14, and so here.
Eigen::Vector4f Diffuse(const aiMaterial& material) {
  aiColor3D c(1, 1, 1);
  material.Get(AI_MATKEY_COLOR_DIFFUSE, c);
  return {c.r, c.g, c.b, 1.f};
}

// loadMaterials() in mesh_loader.cpp: "$clr.emissive" becomes the material's self-illumination.
Eigen::Vector3f Emissive(const aiMaterial& material) {
  aiColor3D c(0, 0, 0);
  material.Get(AI_MATKEY_COLOR_EMISSIVE, c);
  return {c.r, c.g, c.b};
}

// loadMaterials() in mesh_loader.cpp: every "$tex.file" property of a material (one per texture
// map of any type and index) creates a texture unit, and each unit is given the material's
// first diffuse map (GetTexture(aiTextureType_DIFFUSE, 0)) whatever map it was made for.
int TextureUnits(const aiMaterial& material) {
  const std::string_view texture_file = _AI_MATKEY_TEXTURE_BASE;   // "$tex.file"
  int units = 0;
  for (unsigned i = 0; i < material.mNumProperties; ++i) units += material.mProperties[i]->mKey.C_Str() == texture_file;
  return units;
}

// The image RViz's texture units show: the first diffuse map, its name appended to the mesh
// file's folder and a "/" as RViz appends it; "" without a diffuse map, or for an embedded image
// ("*N", which RViz looks for as a file and never finds).
std::string UnitTexture(const aiMaterial& material, const fs::path& mesh_path) {
  aiString name;
  if (material.GetTexture(aiTextureType_DIFFUSE, 0, &name) != aiReturn_SUCCESS || name.length == 0 ||
      name.C_Str()[0] == '*') {
    return "";
  }
  return mesh_path.parent_path().string() + "/" + name.C_Str();
}

struct Builder {
  const fs::path& path;
  const aiScene& scene;
  bool is_stl;
  MeshFile& out;

  [[noreturn]] void Fail(const std::string& message) const {
    throw Error(SourceLocation{path.string()}, message);
  }

  // buildMesh() in mesh_loader.cpp, as RViz 1.14.14 and later have it: a node's meshes are placed
  // by the node's transform after those of its ancestors, where the root node's transform loses
  // its rotation but keeps its scale and translation (assimp's Decompose). assimp turns a COLLADA
  // file's up axis into a rotation of the root and its <unit> into a scale of the root, so the up
  // axis is ignored and the unit honoured; a glTF file whose single node is the root keeps that
  // node's translation and scale but not its rotation. Normals go through the inverse transpose
  // and are renormalised. `parent` is the transform `node`'s parent placed its meshes by.
  void AddNode(const aiNode& node, const aiMatrix4x4& parent) {
    aiMatrix4x4 transform = parent * node.mTransformation;
    if (!node.mParent) {
      aiVector3D scaling, position;
      aiQuaternion rotation;
      node.mTransformation.Decompose(scaling, rotation, position);
      transform = aiMatrix4x4(scaling, aiQuaternion(), position);
    }
    Eigen::Matrix4f X;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) X(r, c) = transform[r][c];
    }
    const Eigen::Matrix3f linear = X.topLeftCorner<3, 3>();
    const Eigen::Vector3f translation = X.topRightCorner<3, 1>();
    const Eigen::Matrix3f normal_matrix = linear.inverse().transpose();
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      // RViz's flags leave out ValidateDataStructure, so indices are checked here
      if (node.mMeshes[i] >= scene.mNumMeshes) Fail("a node refers to a mesh that does not exist");
      AddMesh(*scene.mMeshes[node.mMeshes[i]], linear, translation, normal_matrix);
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) AddNode(*node.mChildren[i], transform);
  }

  void AddMesh(const aiMesh& in, const Eigen::Matrix3f& linear, const Eigen::Vector3f& translation,
               const Eigen::Matrix3f& normal_matrix) {
    // SortByPType leaves point and line meshes apart; RViz would draw their indices as triangles
    if (!(in.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;
    if (!in.HasNormals()) Fail("mesh '" + std::string(in.mName.C_Str()) + "' has no normals after import");
    out.triangle_count += in.mNumFaces;
    if (out.triangle_count > kMaxMeshTriangles) {
      Fail("more than " + std::to_string(kMaxMeshTriangles) + " triangles (the limit)");
    }
    MeshPart part;
    part.takes_urdf_material = is_stl;
    if (!is_stl && in.mMaterialIndex >= scene.mNumMaterials) {
      Fail("mesh '" + std::string(in.mName.C_Str()) + "' refers to a material that does not exist");
    }
    if (!is_stl) {
      const aiMaterial& material = *scene.mMaterials[in.mMaterialIndex];
      part.diffuse = Diffuse(material);
      part.emissive = Emissive(material);
      part.texture_units = TextureUnits(material);
      if (part.texture_units > 0) part.texture = UnitTexture(material, path);
    }
    TriangleMesh& mesh = part.mesh;
    mesh.positions.reserve(in.mNumVertices);
    mesh.normals.reserve(in.mNumVertices);
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
      const aiVector3D& p = in.mVertices[v];
      const aiVector3D& n = in.mNormals[v];
      mesh.positions.push_back(linear * Eigen::Vector3f(p.x, p.y, p.z) + translation);
      mesh.normals.push_back((normal_matrix * Eigen::Vector3f(n.x, n.y, n.z)).normalized());
      if (in.HasTextureCoords(0)) mesh.uvs.emplace_back(in.mTextureCoords[0][v].x, in.mTextureCoords[0][v].y);
    }
    mesh.indices.reserve(3 * std::size_t{in.mNumFaces});
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= in.mNumVertices) {
          Fail("mesh '" + std::string(in.mName.C_Str()) + "' has a triangle with vertex index " +
               std::to_string(face.mIndices[k]) + " of " + std::to_string(in.mNumVertices));
        }
      }
      mesh.indices.insert(mesh.indices.end(), face.mIndices, face.mIndices + 3);
    }
    out.parts.push_back(std::move(part));
  }
};

}  // namespace

MeshFile ReadMeshFile(const fs::path& path) {
  const SourceLocation where{path.string()};
  std::error_code ec;
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (ec) throw Error(where, "cannot read mesh file: " + ec.message());
  if (bytes > kMaxMeshFileBytes) {
    throw Error(where, "mesh file of " + std::to_string(bytes >> 20) +
                           " MiB is over the limit of " + std::to_string(kMaxMeshFileBytes >> 20) +
                           " MiB");
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), kRvizImportFlags);
  if (!scene || !scene->mRootNode)
    throw Error(where, std::string("cannot read mesh file: ") + importer.GetErrorString());
  MeshFile file;
  Builder{path, *scene, IsStlFile(path), file}.AddNode(*scene->mRootNode, aiMatrix4x4());
  if (file.parts.empty())
    throw Error(where, "no triangles in the mesh file");  // RViz: "No meshes found in file"
  return file;
}

}  // namespace urdfsnap::geometry
