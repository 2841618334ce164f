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

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "gl/internal/point_splat.h"
#include "gl/internal/shader_program.h"
#include "scene/scene.h"

struct __GLsync;   // GL/glcorearb.h's GLsync is a pointer to it; GL's headers are kept out of here

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
  // Gives a buffer of at least `words` words, mapped, for the splat to write the composite's texels
  // into once the last composite has read it.
  std::uint32_t* SplatTexels(std::size_t words);
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
  // PointSplat's texels: a buffer texture (rg32ui) over a persistently mapped buffer the splat
  // writes into, so they are not copied; the fence of the last composite that read them
  unsigned splat_texture_ = 0;
  unsigned splat_buffer_ = 0;
  std::uint32_t* splat_texels_ = nullptr;
  std::size_t splat_words_ = 0;
  __GLsync* splat_read_ = nullptr;
};

}  // namespace urdfsnap::gl
