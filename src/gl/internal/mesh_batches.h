// Lit meshes gathered into instanced draws: draw items that share a mesh, a texture and a winding
// become one batch of MeshInstances (gpu_mesh.h), drawn by one glDrawElementsInstanced, instead of
// one draw with its own uniforms each. A thousand markers of a few shapes are a few draws; llvmpipe
// spends per draw, on the calling thread, about what it spends drawing a small shape's triangles.
// Opaque items join the batch of their kind wherever it is (the depth test orders them; Ogre too
// groups opaque renderables by material, not by the order they were made); blended items join only
// the batch just before them, so that the back-to-front order is kept (see DrawBlended in
// scene_renderer.cpp). Internal to the render library; GL-free but for the GpuMesh it is given.
#pragma once

#include <cstddef>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "gl/internal/gpu_mesh.h"
#include "scene/scene.h"

namespace urdfsnap::gl {

// What the instances of one draw share.
struct MeshBatchKey {
  const geometry::TriangleMesh* mesh = nullptr;
  const texture::TextureImage* texture = nullptr;   // null: untextured
  int texture_units = 0;                            // 0 when untextured
  bool mirrored = false;   // a mirroring scale turns the winding around (front faces clockwise)
  bool operator==(const MeshBatchKey&) const = default;
};

struct MeshBatch {
  MeshBatchKey key;
  const GpuMesh* mesh = nullptr;
  const scene::DrawItem* item = nullptr;   // the first item, whose texture the batch shows
  std::vector<MeshInstance> instances;
};

class MeshBatches {
 public:
  // Where an item goes: into the batch of its kind anywhere (opaque), or the last batch only when
  // that is of its kind (blended, in order), else a new batch.
  enum class Join { kAny, kLast };

  // Adds `item` (drawn with `mesh`, its GPU copy; at most `max_texture_units` texture units) seen
  // through view `V` and projection-view `PV`, unless it lies wholly outside the view.
  void Add(const scene::DrawItem& item, const GpuMesh& mesh, int max_texture_units, const Eigen::Matrix4d& V,
           const Eigen::Matrix4d& PV, Join join);

  // The batches in the order their first items were added.
  const std::vector<MeshBatch>& batches() const { return batches_; }
  bool empty() const { return batches_.empty(); }
  void Clear();

 private:
  struct KeyHash {
    std::size_t operator()(const MeshBatchKey& key) const;
  };
  std::vector<MeshBatch> batches_;
  std::unordered_map<MeshBatchKey, std::size_t, KeyHash> index_;   // Join::kAny's batches
};

}  // namespace urdfsnap::gl
