// The GL drawing of the scene parts whose vertices are made anew each frame and streamed through
// one buffer: line sets (1-pixel lines, or camera-facing ribbons as rviz's billboard_line.cpp),
// flat triangle lists (triangle_list_marker.cpp) and text labels (movable_text.cpp). The caller
// sets blending and depth writes; SceneRenderer orders these draws among its passes. Internal to
// the render library; needs a current GL context.
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

  // Draws `lines` (in the fixed frame) with projection-view matrix `PV`: 1-pixel lines, or with a
  // width ribbons turned towards `eye`.
  void DrawLines(const scene::LineSet& lines, const Eigen::Matrix4d& PV, const Eigen::Vector3d& eye);
  // Draws `triangles` (in the fixed frame), both faces, with projection-view matrix `PV`.
  void DrawTriangles(const scene::FlatTriangles& triangles, const Eigen::Matrix4d& PV);
  // Draws `label` seen through view matrix `V` and projection `P`, its characters cut from
  // `glyphs` (the GPU copy of label.texture); `label` has at least one character. Leaves front
  // faces counter-clockwise.
  void DrawLabel(const scene::TextLabel& label, const GpuTexture& glyphs, const Eigen::Matrix4d& V,
                 const Eigen::Matrix4d& P);

 private:
  // Fills the stream buffer with `floats` and sets up attribute i from `sizes[i]` of each vertex.
  void Stream(const std::vector<float>& floats, std::initializer_list<int> sizes);
  ShaderProgram line_;   // position and rgba per vertex: lines and triangles
  LazyShaderProgram text_{"text.vert", "text.frag"};
  unsigned stream_array_ = 0, stream_buffer_ = 0;
};

}  // namespace urdfsnap::gl
