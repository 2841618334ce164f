// A TriangleMesh uploaded to the GPU (vertex array with interleaved position, normal and texture
// coordinates, and an index buffer), drawn once or as many instances (MeshInstance: one pose,
// colour and normal matrix each, read per instance by shaders/lit.vert), with a sphere around its vertices, so that a mesh wholly
// outside the view is not sent down the pipeline at all (Ogre culls such objects too; llvmpipe
// would shade and clip every vertex of it on the render thread to draw nothing). Internal to the
// render library; needs a current GL context.
#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "geometry/triangle_mesh.h"

namespace urdfsnap::gl {

// One drawing of a mesh, as shaders/lit.vert reads it per instance (attributes 3 to 12): where the
// mesh goes (model-view-projection matrix), how its normals turn into the view (the inverse
// transpose of the model-view matrix, which undoes scaling), its diffuse rgba and emissive rgb, and
// its link label (1 + the link's index, 0 for none; read only by the LABELS variant).
// Column-major, as GL takes matrices; 132 bytes.
struct MeshInstance {
  float model_view_projection[16];
  float normal_to_view[9];
  float diffuse[4];
  float emissive[3];
  std::uint32_t label;
};

class GpuMesh {
 public:
  explicit GpuMesh(const geometry::TriangleMesh& mesh);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  int triangles() const { return index_count_ / 3; }

  // Draws the triangles with the program in use (attribute 0 position, 1 normal, 2 uv).
  void Draw() const;
  // Draws `count` instances, the MeshInstances at the start of buffer `instances`, in their order
  // (so blended instances keep it), with the program in use (attributes 0 to 2 as Draw's, 3 to 12
  // the instance's).
  void DrawInstances(unsigned instances, int count) const;
  // Draws, with the MeshInstances at the start of buffer `instances` and the program in use, the
  // `count` index ranges of buffer `commands` (InstanceTriangles, coverage_cull.h: glMultiDraw-
  // ElementsIndirect's commands, each naming its instance) in buffer `indices` (of this mesh's
  // vertices), in their order.
  void DrawInstanceRanges(unsigned instances, unsigned indices, unsigned commands, int count) const;

  // Whether the mesh lies wholly outside the clip volume of `model_view_projection` (the mesh's
  // coordinates to clip space): its bounding sphere is beyond one of the volume's six planes, so
  // drawing it could not touch a pixel. False when unsure (a mesh with a coordinate not finite).
  bool OutsideClipVolume(const Eigen::Matrix4d& model_view_projection) const;
  // The sphere around the vertices (an infinite radius when a coordinate is not finite).
  const Eigen::Vector3d& centre() const { return centre_; }
  double radius() const { return radius_; }

 private:
  // Binds the vertex array with the instance attributes read from buffer `instances`.
  void BindInstances(unsigned instances) const;

  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();   // of the bounding sphere
  double radius_ = 0;
  unsigned vertex_array_ = 0;
  unsigned buffers_[2] = {0, 0};   // vertices, indices
  int index_count_ = 0;
};

}  // namespace urdfsnap::gl
