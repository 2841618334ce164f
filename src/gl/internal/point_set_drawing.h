// The GL drawing of scene::PointSet in RViz's point-cloud styles (rviz/ogre_helpers/point_cloud.cpp
// and its materials in ogre_media/materials): Points as GL points of N pixels, Squares, Flat
// Squares and Spheres as camera-facing squares, Boxes as shaded boxes along the set's axes. The points
// are streamed in batches, four vertices per square and 24 per box sharing one index buffer, so
// the GPU memory stays bounded however many points a set holds. Internal to the render library;
// needs a current GL context.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "gl/internal/shader_program.h"
#include "scene/scene.h"

namespace urdfsnap::gl {

class PointSetDrawing {
 public:
  PointSetDrawing();
  ~PointSetDrawing();
  PointSetDrawing(const PointSetDrawing&) = delete;
  PointSetDrawing& operator=(const PointSetDrawing&) = delete;

  // Draws `points` (in the fixed frame) seen through view matrix `V` and projection `P` with the
  // blending and depth writes the caller has set. Leaves back-face culling on.
  void Draw(const scene::PointSet& points, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P);

 private:
  void Upload(const scene::PointSet& points, size_t first, size_t count, int copies);
  ShaderProgram point_;
  ShaderProgram quad_;
  ShaderProgram box_;
  unsigned vertex_array_ = 0;
  unsigned buffers_[2] = {0, 0};   // vertices (streamed), quad indices (fixed)
  std::vector<unsigned char> staging_;
};

}  // namespace urdfsnap::gl
