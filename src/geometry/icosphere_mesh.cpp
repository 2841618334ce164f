// The unit sphere as rviz_sphere.mesh: a geodesic icosphere (icosahedron with subdivided edges).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "geometry/internal/texture_coordinates.h"
#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry {
namespace {

// The 12 unit icosahedron corners: 0 = +Z pole, 1..5 upper ring, 6..10 lower ring (turned by
// 36 degrees against the upper one), 11 = -Z pole. The poles are corners so that they get
// valence 5, as in RViz's mesh.
std::array<Eigen::Vector3d, 12> IcosahedronCorners() {
  std::array<Eigen::Vector3d, 12> corners;
  const double ring_z = 1.0 / std::sqrt(5.0);
  const double ring_radius = 2.0 / std::sqrt(5.0);
  corners[0] = Eigen::Vector3d::UnitZ();
  for (int k = 0; k < 5; ++k) {
    const double upper = 2.0 * std::numbers::pi * k / 5.0;
    const double lower = upper + std::numbers::pi / 5.0;
    corners[1 + k] = {ring_radius * std::cos(upper), ring_radius * std::sin(upper), ring_z};
    corners[6 + k] = {ring_radius * std::cos(lower), ring_radius * std::sin(lower), -ring_z};
  }
  corners[11] = -Eigen::Vector3d::UnitZ();
  return corners;
}

// The 20 faces over those corners, counter-clockwise seen from outside.
std::vector<std::array<int, 3>> IcosahedronFaces() {
  std::vector<std::array<int, 3>> faces;
  for (int k = 0; k < 5; ++k) {
    const int upper = 1 + k, next_upper = 1 + (k + 1) % 5;
    const int lower = 6 + k, next_lower = 6 + (k + 1) % 5;
    faces.push_back({0, upper, next_upper});
    faces.push_back({upper, lower, next_upper});
    faces.push_back({next_upper, lower, next_lower});
    faces.push_back({11, next_lower, lower});
  }
  return faces;
}

// A point of the subdivided icosahedron, named by the corners it is made of and their weights
// (in edge_divisions-ths, summing to edge_divisions). Points on an edge shared by two faces get
// the same name from both, which is how the faces come to share vertices.
using PointName = std::vector<std::pair<int, int>>;

class IcosphereBuilder {
 public:
  explicit IcosphereBuilder(int edge_divisions)
      : divisions_(edge_divisions), corners_(IcosahedronCorners()) {}

  TriangleMesh Build() {
    const int n = divisions_;
    for (const auto& face : IcosahedronFaces()) {
      // grid point (i, j) of the face is a + i/n (b - a) + j/n (c - a); (no structured binding:
      // clang before 16 cannot capture one in a lambda)
      const int a = face[0], b = face[1], c = face[2];
      const auto at = [&](int i, int j) { return Vertex({{a, n - i - j}, {b, i}, {c, j}}); };
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i + j < n; ++i) {
          // the upright triangle at (i, j) and, where it fits, the upside-down one beside it;
          // both keep the face's counter-clockwise order
          Triangle(at(i, j), at(i + 1, j), at(i, j + 1));
          if (i + j + 2 <= n) Triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        }
      }
    }
    internal::AttachSphereUvs(mesh_);
    return std::move(mesh_);
  }

 private:
  std::uint32_t Vertex(PointName name) {
    std::erase_if(name, [](const auto& part) { return part.second == 0; });
    std::sort(name.begin(), name.end());
    const auto [it, inserted] = index_of_.try_emplace(name, mesh_.positions.size());
    if (inserted) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const auto& [corner, weight] : name) sum += weight * corners_[corner];
      const Eigen::Vector3f direction = sum.normalized().cast<float>();
      mesh_.positions.push_back(0.5f * direction);
      mesh_.normals.push_back(direction);
    }
    return it->second;
  }

  void Triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }

  int divisions_;
  std::array<Eigen::Vector3d, 12> corners_;
  std::map<PointName, std::uint32_t> index_of_;
  TriangleMesh mesh_;
};

}  // namespace

TriangleMesh MakeUnitSphere(int edge_divisions) {
  if (edge_divisions < 1) {
    throw Error("MakeUnitSphere: edge_divisions must be at least 1, got " +
                std::to_string(edge_divisions));
  }
  return IcosphereBuilder(edge_divisions).Build();
}

}  // namespace urdfsnap::geometry
