// Upload, drawing (once or instanced) and view culling of triangle meshes.
#include "gl/internal/gpu_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "gl/internal/gl_api.h"

namespace urdfsnap::gl {

GpuMesh::GpuMesh(const geometry::TriangleMesh& mesh)
    : index_count_(static_cast<int>(mesh.indices.size())) {
  std::vector<float> interleaved;
  interleaved.reserve(mesh.positions.size() * 8);
  const bool has_uvs = mesh.uvs.size() == mesh.positions.size();
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    interleaved.insert(interleaved.end(), mesh.positions[i].data(), mesh.positions[i].data() + 3);
    interleaved.insert(interleaved.end(), mesh.normals[i].data(), mesh.normals[i].data() + 3);
    // without coordinates every vertex samples (0, 0), as Ogre's fixed-function default does
    const Eigen::Vector2f uv = has_uvs ? mesh.uvs[i] : Eigen::Vector2f::Zero();
    interleaved.insert(interleaved.end(), uv.data(), uv.data() + 2);
  }
  glGenVertexArrays(1, &vertex_array_);
  glBindVertexArray(vertex_array_);
  glGenBuffers(2, buffers_);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
               interleaved.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  const GLsizei stride = 8 * sizeof(float);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(6 * sizeof(float)));
  glBindVertexArray(0);
  // the sphere around the bounding box: not the least sphere, but cheap and never too small; one
  // without bounds when a coordinate is not finite (where GL would draw it is not for us to judge)
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3f& p : mesh.positions) {
    if (!p.allFinite()) {
      radius_ = std::numeric_limits<double>::infinity();
      return;
    }
    box.extend(p.cast<double>());
  }
  if (!box.isEmpty()) {
    centre_ = box.center();
    for (const Eigen::Vector3f& p : mesh.positions) radius_ = std::max(radius_, (p.cast<double>() - centre_).norm());
  }
}

GpuMesh::~GpuMesh() {
  glDeleteBuffers(2, buffers_);
  glDeleteVertexArrays(1, &vertex_array_);
}

bool GpuMesh::OutsideClipVolume(const Eigen::Matrix4d& model_view_projection) const {
  // a point p is inside when -w <= x, y, z <= w in clip space: each of the six planes is
  // (row w ± row x, y or z) . (p, 1) >= 0, in the mesh's own coordinates
  const Eigen::Matrix4d& m = model_view_projection;
  const Eigen::Vector4d centre = centre_.homogeneous();
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {1.0, -1.0}) {
      const Eigen::Vector4d plane = m.row(3).transpose() + side * m.row(axis).transpose();
      // beyond the plane by more than the radius (false for NaN, so an unsure mesh is drawn)
      if (plane.dot(centre) < -radius_ * plane.head<3>().norm()) return true;
    }
  }
  return false;
}

void GpuMesh::Draw() const {
  glBindVertexArray(vertex_array_);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::BindInstances(unsigned instances) const {
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, instances);
  // a mat4 takes four attribute locations (one per column), a mat3 three
  struct Attribute {
    int columns, rows;
    std::size_t offset;
  };
  const Attribute attributes[] = {{4, 4, offsetof(MeshInstance, model_view_projection)},
                                  {3, 3, offsetof(MeshInstance, normal_to_view)},
                                  {1, 4, offsetof(MeshInstance, diffuse)},
                                  {1, 3, offsetof(MeshInstance, emissive)}};
  GLuint location = 3;
  for (const Attribute& a : attributes) {
    for (int column = 0; column < a.columns; ++column, ++location) {
      glEnableVertexAttribArray(location);
      glVertexAttribPointer(location, a.rows, GL_FLOAT, GL_FALSE, sizeof(MeshInstance),
                            reinterpret_cast<const void*>(a.offset + column * a.rows * sizeof(float)));
      glVertexAttribDivisor(location, 1);
    }
  }
  glEnableVertexAttribArray(location);
  glVertexAttribIPointer(location, 1, GL_UNSIGNED_INT, sizeof(MeshInstance),
                         reinterpret_cast<const void*>(offsetof(MeshInstance, label)));
  glVertexAttribDivisor(location, 1);
}

void GpuMesh::DrawInstances(unsigned instances, int count) const {
  BindInstances(instances);
  glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, count);
}

void GpuMesh::DrawInstanceRanges(unsigned instances, unsigned indices, unsigned commands, int count) const {
  BindInstances(instances);
  // the element buffer is the vertex array's: lent to `indices` for this draw, then given back
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands);
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, count, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
}

}  // namespace urdfsnap::gl
