// A TriangleMesh uploaded to the GPU (vertex array with interleaved position, normal and texture
// coordinates, and an index buffer). Internal to the render library; needs a current GL context.
#pragma once

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

 private:
  unsigned vertex_array_ = 0;
  unsigned buffers_[2] = {0, 0};   // vertices, indices
  int index_count_ = 0;
};

}  // namespace urdfsnap::gl
