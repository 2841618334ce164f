// MeshBatches: each draw item's instance (its matrices computed in double, then rounded to float,
// as the per-item uniforms were) added to the batch of its mesh, texture and winding.
#include "gl/internal/mesh_batches.h"

#include <algorithm>
#include <functional>

namespace urdfsnap::gl {

namespace {

MeshInstance Instance(const scene::DrawItem& item, const Eigen::Matrix4d& MV, const Eigen::Matrix4d& MVP) {
  MeshInstance instance;
  Eigen::Map<Eigen::Matrix4f>(instance.model_view_projection) = MVP.cast<float>();
  const Eigen::Matrix3d normal_to_view = MV.topLeftCorner<3, 3>().inverse().transpose();
  Eigen::Map<Eigen::Matrix3f>(instance.normal_to_view) = normal_to_view.cast<float>();
  Eigen::Map<Eigen::Vector4f>(instance.diffuse) = item.rgba;
  Eigen::Map<Eigen::Vector3f>(instance.emissive) = item.emissive;
  instance.label = item.link < 0 ? 0 : static_cast<std::uint32_t>(item.link) + 1;
  return instance;
}

}  // namespace

std::size_t MeshBatches::KeyHash::operator()(const MeshBatchKey& key) const {
  const std::hash<const void*> hash;
  return hash(key.mesh) ^ (hash(key.texture) * 31) ^ (static_cast<std::size_t>(key.texture_units) << 1) ^
         static_cast<std::size_t>(key.mirrored);
}

void MeshBatches::Add(const scene::DrawItem& item, const GpuMesh& mesh, int max_texture_units,
                      const Eigen::Matrix4d& V, const Eigen::Matrix4d& PV, Join join) {
  const Eigen::Matrix4d M = item.X_FG.matrix();
  const Eigen::Matrix4d MVP = PV * M;
  if (mesh.OutsideClipVolume(MVP)) return;
  // a texture shown by no unit leaves the colour as it is: such a surface is drawn untextured
  const int units = item.texture ? std::clamp(item.texture_units, 0, max_texture_units) : 0;
  const MeshBatchKey key{item.mesh.get(), units > 0 ? item.texture.get() : nullptr, units,
                         M.topLeftCorner<3, 3>().determinant() < 0};
  MeshBatch* batch = nullptr;
  if (join == Join::kLast) {
    if (!batches_.empty() && batches_.back().key == key) batch = &batches_.back();
  } else if (const auto it = index_.find(key); it != index_.end()) {
    batch = &batches_[it->second];
  }
  if (!batch) {
    if (join == Join::kAny) index_.emplace(key, batches_.size());
    batch = &batches_.emplace_back(MeshBatch{key, &mesh, &item, {}});
  }
  batch->instances.push_back(Instance(item, V * M, MVP));
}

void MeshBatches::Clear() {
  batches_.clear();
  index_.clear();
}

}  // namespace urdfsnap::gl
