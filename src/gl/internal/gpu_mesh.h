// A TriangleMesh uploaded to the GPU (vertex array with interleaved position, normal and texture
// coordinates, and an index buffer) with a sphere around its vertices, so that a mesh wholly
// outside the view is not sent down the pipeline at all (Ogre culls such objects too; llvmpipe
// would shade and clip every vertex of it on the render thread to draw nothing). Internal to the
// render library; needs a current GL context.
#pragma once

#include <Eigen/Core>

#include "geometry/triangle_mesh.h"

namespace urdfsnap::gl {

class GpuMesh {
 public:
  explicit GpuMesh(const geometry::TriangleMesh& mesh);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  // Draws the triangles with the program in use (attribute 0 position, 1 normal, 2 uv).
  void Draw() const;

  // Whether the mesh lies wholly outside the clip volume of `model_view_projection` (the mesh's
  // coordinates to clip space): its bounding sphere is beyond one of the volume's six planes, so
  // drawing it could not touch a pixel. False when unsure (a mesh with a coordinate not finite).
  bool OutsideClipVolume(const Eigen::Matrix4d& model_view_projection) const;

 private:
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();   // of the bounding sphere
  double radius_ = 0;
  unsigned vertex_array_ = 0;
  unsigned buffers_[2] = {0, 0};   // vertices, indices
  int index_count_ = 0;
};

}  // namespace urdfsnap::gl
