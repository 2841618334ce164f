// Tessellated primitives checked by invariants (after Drake's internal_shape_meshes_test.cc):
// counts as RViz's meshes have them, unit normals, outward counter-clockwise winding that agrees
// with the vertex normals, closed surfaces, and areas converging to the analytic ones.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "common/error.h"
#include "geometry/triangle_mesh.h"

namespace urdfsnap::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Vector3f Corner(const TriangleMesh& mesh, int triangle, int corner) {
  return mesh.positions[mesh.indices[3 * triangle + corner]];
}

// Twice the area, along the counter-clockwise normal.
Eigen::Vector3f AreaVector(const TriangleMesh& mesh, int triangle) {
  const Eigen::Vector3f a = Corner(mesh, triangle, 0);
  return (Corner(mesh, triangle, 1) - a).cross(Corner(mesh, triangle, 2) - a);
}

double SurfaceArea(const TriangleMesh& mesh) {
  double area = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t) area += 0.5 * AreaVector(mesh, t).norm();
  return area;
}

void ExpectWellFormed(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.positions.size(), mesh.normals.size());
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (const std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size());
  for (const Eigen::Vector3f& n : mesh.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-6);
  // every vertex is used
  const std::set<std::uint32_t> used(mesh.indices.begin(), mesh.indices.end());
  EXPECT_EQ(used.size(), mesh.positions.size());
}

// Every unit primitive is convex around the origin, so a triangle facing outward has its
// counter-clockwise normal pointing away from the origin, and towards its vertices' normals.
void ExpectOutwardWinding(const TriangleMesh& mesh) {
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const Eigen::Vector3f face_normal = AreaVector(mesh, t).normalized();
    const Eigen::Vector3f centroid =
        (Corner(mesh, t, 0) + Corner(mesh, t, 1) + Corner(mesh, t, 2)) / 3.f;
    EXPECT_GT(face_normal.dot(centroid.normalized()), 0.f) << "triangle " << t;
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(face_normal.dot(mesh.normals[mesh.indices[3 * t + c]]), 0.f)
          << "triangle " << t << " corner " << c;
    }
  }
}

// Closed and consistently oriented: every directed edge (a, b) meets its reverse (b, a) exactly
// once, compared by position since flat faces do not share vertices with their neighbours.
void ExpectClosed(const TriangleMesh& mesh) {
  const auto key = [&](std::uint32_t i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    return std::tuple{std::lround(p.x() * 1e5), std::lround(p.y() * 1e5), std::lround(p.z() * 1e5)};
  };
  std::map<std::pair<decltype(key(0)), decltype(key(0))>, int> directed;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    for (int c = 0; c < 3; ++c) {
      ++directed[{key(mesh.indices[3 * t + c]), key(mesh.indices[3 * t + (c + 1) % 3])}];
    }
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    const auto reverse = directed.find({edge.second, edge.first});
    ASSERT_NE(reverse, directed.end());
    EXPECT_EQ(reverse->second, 1);
  }
}

void ExpectWithinUnitBox(const TriangleMesh& mesh) {
  for (const Eigen::Vector3f& p : mesh.positions) {
    EXPECT_LE(p.cwiseAbs().maxCoeff(), 0.5f + 1e-6f);
  }
}

// Relative area errors at rising resolution fall and end below `final_tolerance`.
void ExpectAreaConverges(const std::function<TriangleMesh(int)>& make, double analytic,
                         std::initializer_list<int> resolutions, double final_tolerance) {
  double previous_error = INFINITY;
  for (const int resolution : resolutions) {
    const double error = std::abs(SurfaceArea(make(resolution)) - analytic) / analytic;
    EXPECT_LT(error, previous_error) << "resolution " << resolution;
    previous_error = error;
  }
  EXPECT_LT(previous_error, final_tolerance);
}

struct Shape {
  const char* name;
  std::function<TriangleMesh()> make;
  int vertices;
  int triangles;
};
void PrintTo(const Shape& shape, std::ostream* os) { *os << shape.name; }

class PrimitiveMeshTest : public testing::TestWithParam<Shape> {};

TEST_P(PrimitiveMeshTest, CountsMatchRviz) {
  const TriangleMesh mesh = GetParam().make();
  EXPECT_EQ(mesh.vertex_count(), GetParam().vertices);
  EXPECT_EQ(mesh.triangle_count(), GetParam().triangles);
}

TEST_P(PrimitiveMeshTest, WellFormedWithUnitNormals) { ExpectWellFormed(GetParam().make()); }
TEST_P(PrimitiveMeshTest, WoundCounterClockwiseFromOutside) {
  ExpectOutwardWinding(GetParam().make());
}
TEST_P(PrimitiveMeshTest, ClosedSurface) { ExpectClosed(GetParam().make()); }
TEST_P(PrimitiveMeshTest, FitsTheUnitBox) { ExpectWithinUnitBox(GetParam().make()); }

INSTANTIATE_TEST_SUITE_P(Rviz, PrimitiveMeshTest,
                         testing::Values(
                             // rviz_cube.mesh: 6 faces x 4 vertices, 2 triangles each
                             Shape{"box", MakeUnitBox, 24, 12},
                             // rviz_cylinder.mesh: 40 segments, 80 side and 2 x 40 cap triangles;
                             // plus copies of the 4 vertices where the texture wraps
                             Shape{"cylinder", [] { return MakeUnitCylinder(); }, 4 * 40 + 2 + 4, 160},
                             // rviz_sphere.mesh: icosahedron with edges split in 6; plus copies
                             // of the 17 seam vertices and 4 more of each pole (one per triangle)
                             Shape{"sphere", [] { return MakeUnitSphere(); }, 362 + 17 + 8, 720},
                             Shape{"cone", [] { return MakeUnitCone(); }, 3 * 40 + 1, 80},
                             // the smallest allowed resolutions still make sound meshes
                             Shape{"cylinder3", [] { return MakeUnitCylinder(3); }, 14 + 4, 12},
                             Shape{"sphere1", [] { return MakeUnitSphere(1); }, 12 + 2 + 8, 20},
                             Shape{"cone3", [] { return MakeUnitCone(3); }, 10, 6}),
                         [](const testing::TestParamInfo<Shape>& info) {
                           return std::string(info.param.name);
                         });

TEST(BoxMeshTest, FacesAreFlatAndAxisAligned) {
  const TriangleMesh mesh = MakeUnitBox();
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    // the normal is the one axis along which the vertex sits on the surface
    const Eigen::Vector3f& n = mesh.normals[i];
    EXPECT_FLOAT_EQ(n.cwiseAbs().sum(), 1.f);
    EXPECT_FLOAT_EQ(mesh.positions[i].dot(n), 0.5f);
  }
  EXPECT_NEAR(SurfaceArea(mesh), 6.0, 1e-6);
}

TEST(CylinderMeshTest, SideIsSmoothAndStartsAtPlusX) {
  const TriangleMesh mesh = MakeUnitCylinder();
  EXPECT_TRUE(mesh.positions[0].isApprox(Eigen::Vector3f(0.5f, 0.f, -0.5f)));
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    const Eigen::Vector3f& n = mesh.normals[i];
    EXPECT_NEAR(std::abs(p.z()), 0.5, 1e-6);
    if (n.z() == 0.f) {
      // side vertex: on the radius, normal radial
      EXPECT_NEAR(p.head<2>().norm(), 0.5, 1e-6);
      EXPECT_TRUE(n.head<2>().isApprox(2.f * p.head<2>(), 1e-5f));
    } else {
      // cap vertex: flat normal along the axis, on the same side as the cap
      EXPECT_FLOAT_EQ(n.z(), 2.f * p.z());
    }
  }
}

TEST(CylinderMeshTest, AreaConverges) {
  // 2 pi r h + 2 pi r^2 with r = 0.5, h = 1
  ExpectAreaConverges(MakeUnitCylinder, 1.5 * kPi, {3, 10, 40, 400}, 1e-4);
}

TEST(SphereMeshTest, VerticesOnTheRadiusWithRadialNormals) {
  const TriangleMesh mesh = MakeUnitSphere();
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    EXPECT_NEAR(mesh.positions[i].norm(), 0.5, 1e-6);
    EXPECT_TRUE(mesh.normals[i].isApprox(2.f * mesh.positions[i], 1e-5f));
  }
}

TEST(SphereMeshTest, PolesHaveFiveNeighbours) {
  const TriangleMesh mesh = MakeUnitSphere();
  for (const float pole_z : {0.5f, -0.5f}) {
    int pole = -1;
    for (int i = 0; i < mesh.vertex_count(); ++i) {
      if (mesh.positions[i].isApprox(Eigen::Vector3f(0.f, 0.f, pole_z))) pole = i;
    }
    ASSERT_GE(pole, 0) << "no vertex at z = " << pole_z;
    // by position: the pole and the seam have a copy per texture coordinate
    const auto at = [&](std::uint32_t i) {
      const Eigen::Vector3f& p = mesh.positions[i];
      return std::tuple{std::lround(p.x() * 1e5), std::lround(p.y() * 1e5), std::lround(p.z() * 1e5)};
    };
    std::set<decltype(at(0))> neighbours;
    for (int t = 0; t < mesh.triangle_count(); ++t) {
      for (int c = 0; c < 3; ++c) {
        if (at(mesh.indices[3 * t + c]) != at(pole)) continue;
        neighbours.insert(at(mesh.indices[3 * t + (c + 1) % 3]));
        neighbours.insert(at(mesh.indices[3 * t + (c + 2) % 3]));
      }
    }
    EXPECT_EQ(neighbours.size(), 5u) << "pole at z = " << pole_z;
  }
}

TEST(SphereMeshTest, AreaConverges) {
  // 4 pi r^2 with r = 0.5; RViz's 6 divisions already come within 1%
  ExpectAreaConverges(MakeUnitSphere, kPi, {1, 2, 6, 20}, 1e-3);
  EXPECT_LT(std::abs(SurfaceArea(MakeUnitSphere()) - kPi) / kPi, 0.01);
}

// Texture coordinates as in RViz's mesh files (values read from Debian's rviz 1.14.19
// ogre_media/models with the Ogre mesh format): one per vertex, and no triangle spans the wrap.
// Corners on the Z axis (cap centres, poles) have no angle and are left out.
void ExpectUvsWithoutWrap(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    float low = 2, high = -2;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t i = mesh.indices[3 * t + c];
      if (mesh.positions[i].head<2>().isZero()) continue;
      low = std::min(low, mesh.uvs[i].x());
      high = std::max(high, mesh.uvs[i].x());
    }
    EXPECT_LE(high - low, 0.5f) << "triangle " << t;
  }
}

// The coordinates of the vertex at `position` (the first copy).
Eigen::Vector2f UvAt(const TriangleMesh& mesh, const Eigen::Vector3f& position) {
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    if (mesh.positions[i].isApprox(position, 1e-4f)) return mesh.uvs[i];
  }
  ADD_FAILURE() << "no vertex at " << position.transpose();
  return {};
}

TEST(TextureCoordinatesTest, BoxFacesEachShowTheWholeImageAsRvizCube) {
  const TriangleMesh mesh = MakeUnitBox();
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
  // rviz_cube.mesh, +Z face: (-0.5, -0.5) at (0, 1), (0.5, 0.5) at (1, 0); +X face: v = 0 at the top
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    const Eigen::Vector2f& uv = mesh.uvs[i];
    EXPECT_TRUE((uv.array() == 0 || uv.array() == 1).all()) << uv.transpose();
    if (mesh.normals[i].z() == 1) {
      EXPECT_EQ(uv, Eigen::Vector2f(p.x() + 0.5f, 0.5f - p.y()));
    }
    if (mesh.normals[i].x() == 1) {
      EXPECT_EQ(uv, Eigen::Vector2f(p.y() + 0.5f, 0.5f - p.z()));
    }
  }
}

TEST(TextureCoordinatesTest, CylinderWrapsAroundFromThreeQuartersAsRvizCylinder) {
  const TriangleMesh mesh = MakeUnitCylinder();
  ExpectUvsWithoutWrap(mesh);
  // rviz_cylinder.mesh: u = 0.75 at +X, v = 0 at the bottom and 1 at the top; the caps' centres
  // at u = 0.5
  EXPECT_TRUE(UvAt(mesh, {0.5f, 0, -0.5f}).isApprox(Eigen::Vector2f(0.75f, 0)));
  EXPECT_TRUE(UvAt(mesh, {0.5f, 0, 0.5f}).isApprox(Eigen::Vector2f(0.75f, 1)));
  EXPECT_TRUE(UvAt(mesh, {0, 0, 0.5f}).isApprox(Eigen::Vector2f(0.5f, 1)));
}

TEST(TextureCoordinatesTest, SphereIsMappedByLongitudeAndLatitudeAsRvizSphere) {
  const TriangleMesh mesh = MakeUnitSphere();
  ExpectUvsWithoutWrap(mesh);
  // rviz_sphere.mesh: (0.0917, 0, 0.4915) at (0.5, 0.0587), (0.0283, 0.0872, 0.4915) at u = 0.7:
  // u = 0.5 + longitude / 2π (up to whole turns), v = colatitude / π
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    EXPECT_NEAR(mesh.uvs[i].y(), std::acos(2 * p.z()) / kPi, 1e-5);
    if (p.head<2>().isZero()) continue;
    const double u = 0.5 + std::atan2(p.y(), p.x()) / (2 * kPi);
    EXPECT_NEAR(std::remainder(mesh.uvs[i].x() - u, 1.0), 0, 1e-5) << p.transpose();
  }
  // the pole takes the mean of its triangle's other corners: 0.6 between 0.5 and 0.7
  bool found = false;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const Eigen::Vector2f& a = mesh.uvs[mesh.indices[3 * t]];
    if (mesh.positions[mesh.indices[3 * t]].z() == 0.5f && std::abs(a.x() - 0.6f) < 1e-4f) found = true;
  }
  EXPECT_TRUE(found);
}

TEST(ConeMeshTest, ApexAndBase) {
  const TriangleMesh mesh = MakeUnitCone();
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3f& p = mesh.positions[i];
    if (p.z() > 0) {
      EXPECT_TRUE(p.isApprox(Eigen::Vector3f(0.f, 0.f, 0.5f)));
    } else {
      EXPECT_FLOAT_EQ(p.z(), -0.5f);
    }
  }
}

TEST(ConeMeshTest, AreaConverges) {
  // pi r s + pi r^2 with r = 0.5 and slant s = sqrt(r^2 + h^2), h = 1
  ExpectAreaConverges(MakeUnitCone, kPi * 0.5 * std::sqrt(1.25) + kPi * 0.25, {3, 10, 40, 400},
                      1e-4);
}

TEST(PrimitiveMeshTest, RefusesTooFewSegments) {
  EXPECT_THROW(MakeUnitCylinder(2), Error);
  EXPECT_THROW(MakeUnitCone(0), Error);
  EXPECT_THROW(MakeUnitSphere(0), Error);
  try {
    MakeUnitCylinder(2);
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "MakeUnitCylinder: segments must be at least 3, got 2");
  }
}

}  // namespace
}  // namespace urdfsnap::geometry
