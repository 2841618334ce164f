// Which triangles of a batch's small instances can cover a sample: the others are dropped on the
// CPU before llvmpipe sees them, so that a marker sphere a few pixels wide costs its few covering
// triangles instead of 720 (llvmpipe sets up, bins and tests the coverage of every triangle sent,
// on its rasteriser threads, whether or not it covers a sample). A triangle is dropped when it is
// back-facing by a clear margin (GL culls it) or when the box around its window-space corners,
// widened by a bound on the float error of the vertex shader and llvmpipe's snapping, holds no
// sample position of the framebuffer: neither makes a fragment, so drawing the survivors in the
// same order with the same vertices, shader and instance data gives the same bytes as drawing all.
// Only instances wholly inside the clip volume (nothing clipped, every w > 0) and small on screen
// for their triangle count are culled; the rest are drawn whole. Internal to the render library;
// GL-free (the caller asks GL for the viewport and sample positions).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "geometry/triangle_mesh.h"
#include "gl/internal/gpu_mesh.h"

namespace urdfsnap::gl {

// One instance's triangles in a stream of indices, as GL's DrawElementsIndirectCommand lays out
// an entry of glMultiDrawElementsIndirect's buffer.
struct InstanceTriangles {
  std::uint32_t count = 0;            // indices, three per triangle
  std::uint32_t instance_count = 1;
  std::uint32_t first_index = 0;      // where they start in the index stream
  std::int32_t base_vertex = 0;
  std::uint32_t base_instance = 0;    // the instance (its MeshInstance in the batch)
};

class CoverageCull {
 public:
  // A framebuffer of `width` x `height` pixels whose samples lie at `samples` within each pixel
  // ((0.5, 0.5) alone when it is not multisampled), as glGetMultisamplefv gives them.
  CoverageCull(int width, int height, std::vector<Eigen::Vector2f> samples);

  // Fills `indices` and `commands` with what to draw of the `instances` of `mesh` (whose vertices
  // lie within `radius` of `centre`; front faces clockwise when `clockwise`): for each instance in
  // order its triangles that may cover a sample, or all of them. Returns false (and leaves both
  // empty) when no instance is worth culling: the batch is then best drawn as it is.
  bool Cull(const geometry::TriangleMesh& mesh, const Eigen::Vector3d& centre, double radius, bool clockwise,
            const std::vector<MeshInstance>& instances, std::vector<std::uint32_t>& indices,
            std::vector<InstanceTriangles>& commands);

 private:
  // The margin in pixels by which window-space positions of the instance with projection
  // `mvp` may be off, or a negative number when it is not culled (not wholly in the clip volume,
  // or large on screen for its `triangles`).
  double Margin(const Eigen::Matrix4d& mvp, const Eigen::Vector3d& centre, double radius, int triangles) const;
  // Whether the triangle of window-space corners `a`, `b`, `c` (each off by at most `slack`
  // pixels from where llvmpipe puts it) may make a fragment: it does not face away by more than
  // the slack allows, and a sample lies inside it or within the slack of an edge.
  bool Drawn(const Eigen::Vector2f& a, const Eigen::Vector2f& b, const Eigen::Vector2f& c, float slack) const;

  int width_, height_;
  std::vector<Eigen::Vector2f> samples_;
  Eigen::Array4f sample_x_, sample_y_;   // the first four samples' x and y, as vectors
  bool clockwise_ = false;                 // the batch's front faces
  std::vector<Eigen::Vector2f> window_;   // an instance's vertices in window coordinates
};

}  // namespace urdfsnap::gl
