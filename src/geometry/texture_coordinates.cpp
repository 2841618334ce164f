// Texture coordinates of RViz's primitive meshes, with seam and pole vertices split.
#include "geometry/internal/texture_coordinates.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <Eigen/Geometry>

namespace urdfsnap::geometry::internal {

namespace {

constexpr float kTurn = 2 * std::numbers::pi_v<float>;

bool OnAxis(const Eigen::Vector3f& p) { return std::abs(p.x()) < 1e-6f && std::abs(p.y()) < 1e-6f; }

// Corner coordinates of every triangle from `uv_of` (a position's coordinates). A triangle whose
// corners' u span more than half a turn straddles the wrap: its corners above 0.5 move down by one,
// as in RViz's meshes (textures repeat, so u - 1 is the same place on the image). Corners on the
// Z axis, where u means nothing, get `axis_u` or, when that is negative, the mean u of the others.
template <typename UvOf>
std::vector<Eigen::Vector2f> AngularCornerUvs(const TriangleMesh& mesh, UvOf uv_of, float axis_u) {
  std::vector<Eigen::Vector2f> corner_uvs;
  corner_uvs.reserve(mesh.indices.size());
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    Eigen::Vector2f corners[3];
    bool on_axis[3];
    float low = 1, high = 0, sum = 0;
    int around = 0;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3f& p = mesh.positions[mesh.indices[t + c]];
      corners[c] = uv_of(p);
      on_axis[c] = OnAxis(p);
      if (on_axis[c]) continue;
      low = std::min(low, corners[c].x());
      high = std::max(high, corners[c].x());
    }
    for (int c = 0; c < 3; ++c) {
      if (on_axis[c]) continue;
      if (high - low > 0.5f && corners[c].x() > 0.5f) corners[c].x() -= 1;
      sum += corners[c].x();
      ++around;
    }
    for (int c = 0; c < 3; ++c) {
      if (on_axis[c]) corners[c].x() = axis_u >= 0 ? axis_u : sum / static_cast<float>(around);
    }
    corner_uvs.insert(corner_uvs.end(), corners, corners + 3);
  }
  return corner_uvs;
}

}  // namespace

void AttachCornerUvs(TriangleMesh& mesh, const std::vector<Eigen::Vector2f>& corner_uvs) {
  const size_t original = mesh.positions.size();
  mesh.uvs.assign(original, Eigen::Vector2f::Zero());
  std::vector<bool> assigned(original, false);
  // copies made so far, by original vertex and coordinates
  std::map<std::pair<std::uint32_t, std::pair<float, float>>, std::uint32_t> copies;
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    const std::uint32_t vertex = mesh.indices[i];
    const Eigen::Vector2f& uv = corner_uvs[i];
    if (!assigned[vertex]) {
      mesh.uvs[vertex] = uv;
      assigned[vertex] = true;
    } else if (mesh.uvs[vertex] != uv) {
      const auto [it, inserted] =
          copies.try_emplace({vertex, {uv.x(), uv.y()}}, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) {
        mesh.positions.push_back(mesh.positions[vertex]);
        mesh.normals.push_back(mesh.normals[vertex]);
        mesh.uvs.push_back(uv);
      }
      mesh.indices[i] = it->second;
    }
  }
}

void AttachBoxUvs(TriangleMesh& mesh) {
  mesh.uvs.clear();
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    const Eigen::Vector3f& n = mesh.normals[i];
    const Eigen::Vector3f up = std::abs(n.z()) > 0.5f ? Eigen::Vector3f::UnitY() : Eigen::Vector3f::UnitZ();
    mesh.uvs.emplace_back(0.5f + p.dot(up.cross(n)), 0.5f - p.dot(up));
  }
}

void AttachCylinderUvs(TriangleMesh& mesh) {
  const auto uv_of = [](const Eigen::Vector3f& p) {
    const float u = 0.75f + std::atan2(-p.y(), p.x()) / kTurn;
    return Eigen::Vector2f(u - std::floor(u), p.z() + 0.5f);
  };
  AttachCornerUvs(mesh, AngularCornerUvs(mesh, uv_of, /*axis_u=*/0.5f));
}

void AttachSphereUvs(TriangleMesh& mesh) {
  const auto uv_of = [](const Eigen::Vector3f& p) {
    return Eigen::Vector2f(0.5f + std::atan2(p.y(), p.x()) / kTurn,
                           std::acos(std::clamp(p.z() / p.norm(), -1.f, 1.f)) / std::numbers::pi_v<float>);
  };
  AttachCornerUvs(mesh, AngularCornerUvs(mesh, uv_of, /*axis_u=*/-1.f));
}

}  // namespace urdfsnap::geometry::internal
