// Indexed triangle meshes of the unit primitives URDF can name (box, cylinder, sphere) plus the
// arrow-head cone, tessellated as RViz's own mesh files in ogre_media/models are, so that shading
// and silhouettes match RViz. Pure geometry: no GL, no URDF. Callers scale the unit meshes.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace urdfsnap::geometry {

// A triangle list over shared vertices. Positions are in metres of the unit shape.
struct TriangleMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;  // unit length, one per position
  std::vector<std::uint32_t> indices;    // three per triangle, counter-clockwise seen from outside
  // texture coordinates, one per position, or none; v = 0 is the image's top row (Ogre's and
  // assimp's with aiProcess_FlipUVs)
  std::vector<Eigen::Vector2f> uvs;

  int vertex_count() const { return static_cast<int>(positions.size()); }
  int triangle_count() const { return static_cast<int>(indices.size() / 3); }
};

// The cube [-0.5, 0.5]^3 with six flat faces, each two triangles over its own four vertices
// (24 vertices, 12 triangles), as rviz_cube.mesh. Scale by the URDF box size.
TriangleMesh MakeUnitBox();

// A cylinder of radius 0.5 along Z with z in [-0.5, 0.5] (rviz_cylinder.mesh lies along its Y
// axis; RViz turns it +90 degrees about X in robot_link.cpp, so it is stored here already turned).
// `segments` vertices around at equal angles, one at angle 0 (+X); smooth radial side normals; flat
// caps as triangle fans around a centre vertex. 4*segments+2 vertices, 4*segments triangles. Scale
// by (2r, 2r, length). Throws urdfsnap::Error if segments < 3.
TriangleMesh MakeUnitCylinder(int segments = 40);

// A geodesic icosphere of radius 0.5 as rviz_sphere.mesh: an icosahedron with a vertex at each pole
// (+Z and -Z, each with 5 neighbours) whose edges are split in `edge_divisions` parts, projected
// onto the sphere, with smooth normals. 10*d^2+2 vertices and 20*d^2 triangles; RViz's d = 6 gives
// 362 and 720. Scale by the URDF diameter. Throws urdfsnap::Error if edge_divisions < 1.
TriangleMesh MakeUnitSphere(int edge_divisions = 6);

// RViz's arrow-head cone (rviz_cone.mesh turned like the cylinder): apex at z = +0.5, base of
// radius 0.5 at z = -0.5, `segments` vertices around starting at +X, smooth side normals (each side
// triangle has its own apex vertex whose normal points between its two base vertices), flat base
// as a fan. 3*segments+1 vertices, 2*segments triangles. Throws urdfsnap::Error if segments < 3.
TriangleMesh MakeUnitCone(int segments = 40);

}  // namespace urdfsnap::geometry
