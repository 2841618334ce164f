// The GL drawing of the scene parts whose vertices are made anew each frame and streamed through
// one buffer: line sets (1-pixel lines, or camera-facing ribbons as rviz's billboard_line.cpp),
// flat triangle lists (triangle_list_marker.cpp) and text labels (movable_text.cpp), queued and
// drawn together while they can be (consecutive line sets and triangles, consecutive labels of one
// glyph texture). The caller sets blending and depth writes; SceneRenderer orders these draws
// among its passes. Internal to the render library; needs a current GL context.
#pragma once

#include <initializer_list>
#include <vector>

#include <Eigen/Core>

#include "gl/internal/gpu_texture.h"
#include "gl/internal/shader_program.h"
#include "scene/scene.h"

namespace urdfsnap::gl {

class StreamedDrawing {
 public:
  StreamedDrawing();
  ~StreamedDrawing();
  StreamedDrawing(const StreamedDrawing&) = delete;
  StreamedDrawing& operator=(const StreamedDrawing&) = delete;

  // Queues `lines` (in the fixed frame) to be drawn with projection-view matrix `PV`: 1-pixel
  // lines, or with a width ribbons turned towards `eye`. Queued lines and triangles are drawn by
  // Flush, in the order queued, as one draw while they share the primitive and `PV` (blending then
  // goes primitive by primitive, as with a draw each).
  void AddLines(const scene::LineSet& lines, const Eigen::Matrix4d& PV, const Eigen::Vector3d& eye);
  // Queues `triangles` (in the fixed frame), both faces, with projection-view matrix `PV`.
  void AddTriangles(const scene::FlatTriangles& triangles, const Eigen::Matrix4d& PV);
  // Draws what is queued with the blending and depth writes set now; the caller flushes before
  // drawing anything else or changing them.
  void Flush();
  // Queues `label` seen through view matrix `V` and projection `P`, its characters cut from
  // `glyphs` (the GPU copy of label.texture, which must live until Flush): drawn by Flush with the
  // labels queued before it while they share `glyphs` and `P`. Flushing labels leaves front faces
  // counter-clockwise.
  void AddLabel(const scene::TextLabel& label, const GpuTexture& glyphs, const Eigen::Matrix4d& V,
                const Eigen::Matrix4d& P);

 private:
  // Fills the stream buffer with `floats` and sets up attribute i from `sizes[i]` of each vertex.
  void Stream(const std::vector<float>& floats, std::initializer_list<int> sizes);
  void DrawQueuedLabels();
  ShaderProgram line_;   // position and rgba per vertex: lines and triangles
  LazyShaderProgram text_{"text.vert", "text.frag"};
  unsigned stream_array_ = 0, stream_buffer_ = 0;
  // what is queued: lines' or triangles' vertices (position, rgba) with their GL primitive and
  // projection-view matrix, or labels' (offset, uv, anchor in view space, rgba) with their glyph
  // texture and projection
  static constexpr unsigned kNothingQueued = ~0u;
  std::vector<float> queued_;
  unsigned queued_mode_ = kNothingQueued;
  const GpuTexture* queued_glyphs_ = nullptr;
  Eigen::Matrix4d queued_matrix_ = Eigen::Matrix4d::Zero();
};

}  // namespace urdfsnap::gl
