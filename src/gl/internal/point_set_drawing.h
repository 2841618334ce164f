// The GL drawing of scene::PointSet in RViz's point-cloud styles (rviz/ogre_helpers/point_cloud.cpp
// and its materials in ogre_media/materials): Points as GL points of N pixels, Squares, Flat
// Squares and Spheres as camera-facing squares, Boxes as shaded boxes along the set's axes. The points
// are streamed in batches, a vertex per GL point and per corner of a square (4) or box (24, which
// corner from gl_VertexID in the shaders), so the GPU memory stays bounded however many points a set
// holds; opaque sets of one look are one draw. Opaque camera-facing sets are
// splatted on the CPU instead (point_splat.h) and composited by one draw over the tiles it reached, when a frame has enough
// of their points to make that cheaper (PointSplat::kFewestPoints). Internal to the render
// library; needs a current GL context.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "gl/internal/point_splat.h"
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
  // The same for `sets` of one style, size and box axes, as one draw (their points in order).
  void Draw(std::span<const scene::PointSet* const> sets, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P);
  // Draws the opaque `sets` into the bound framebuffer (depth-tested, writing depth, not blending):
  // the camera-facing ones splatted together and composited once (when they have at least
  // PointSplat::kFewestPoints squares' worth, PointSplat::GlCost), Boxes and fewer points through Draw,
  // a draw per look (style, size, box axes).
  void DrawOpaque(const std::vector<const scene::PointSet*>& sets, const Eigen::Matrix4d& V,
                  const Eigen::Matrix4d& P);

 private:
  void Composite();
  // a place in a list of point sets: set index, point index within it
  struct Cursor {
    size_t set = 0, point = 0;
  };
  void Upload(std::span<const scene::PointSet* const> sets, Cursor& cursor, size_t count, size_t copies);
  void HoldQuads(size_t quads);
  ShaderProgram point_;
  ShaderProgram quad_;
  ShaderProgram box_;
  unsigned vertex_array_ = 0;
  unsigned buffers_[2] = {0, 0};   // vertices (streamed), quad indices (HoldQuads)
  size_t quads_held_ = 0;          // squares the index buffer holds
  std::vector<unsigned char> staging_;
  ShaderProgram splat_program_;
  PointSplat splat_;
  unsigned splat_array_ = 0;                    // the composite's corners
  unsigned splat_corners_ = 0;                  // their buffer: clip-space x, y
  unsigned splat_texture_ = 0;                  // PointSplat's texels
  int texture_size_[2] = {0, 0};                // their width and height in texels
};

}  // namespace urdfsnap::gl
