// Line sets, flat triangles and text labels into GL: their vertices built on the CPU each frame
// and streamed through one buffer; consecutive line sets and triangles, and consecutive labels of
// one glyph texture, gathered into one draw.
#include "gl/internal/streamed_drawing.h"

#include "gl/internal/gl_api.h"

namespace urdfsnap::gl {

namespace {

// Appends one vertex of the line shader: position, then rgba.
void AppendVertex(const Eigen::Vector3f& p, const Eigen::Vector4f& rgba, std::vector<float>& floats) {
  floats.insert(floats.end(), p.data(), p.data() + 3);
  floats.insert(floats.end(), rgba.data(), rgba.data() + 4);
}

Eigen::Vector4f PointColour(const scene::LineSet& lines, size_t i) {
  return i < lines.colours.size() ? lines.colours[i] : lines.rgba;
}

// billboard_line.cpp: each segment a quad `width` wide, its sides offset from the segment by half
// the width along the direction across both the segment and the line of sight from `eye`; appended
// to `floats` as two triangles.
void AppendRibbon(const scene::LineSet& lines, const Eigen::Vector3d& eye, std::vector<float>& floats) {
  for (size_t i = 0; i + 1 < lines.points.size(); i += 2) {
    const Eigen::Vector3f a = lines.points[i], b = lines.points[i + 1];
    const Eigen::Vector3f sight = (a + b) / 2 - eye.cast<float>();
    Eigen::Vector3f across = (b - a).cross(sight);
    if (across.squaredNorm() == 0) continue;   // a point, or seen end on
    across = across.normalized() * (lines.width / 2);
    const Eigen::Vector4f ca = PointColour(lines, i), cb = PointColour(lines, i + 1);
    const Eigen::Vector3f a0 = a - across, a1 = a + across, b0 = b - across, b1 = b + across;
    AppendVertex(a0, ca, floats), AppendVertex(a1, ca, floats), AppendVertex(b1, cb, floats);
    AppendVertex(a0, ca, floats), AppendVertex(b1, cb, floats), AppendVertex(b0, cb, floats);
  }
}

}  // namespace

StreamedDrawing::StreamedDrawing() : line_("line.vert", "line.frag") {
  glGenVertexArrays(1, &stream_array_);
  glGenBuffers(1, &stream_buffer_);
}

StreamedDrawing::~StreamedDrawing() {
  glDeleteBuffers(1, &stream_buffer_);
  glDeleteVertexArrays(1, &stream_array_);
}

void StreamedDrawing::Stream(const std::vector<float>& floats, std::initializer_list<int> sizes) {
  glBindVertexArray(stream_array_);
  glBindBuffer(GL_ARRAY_BUFFER, stream_buffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(floats.size() * sizeof(float)), floats.data(),
               GL_STREAM_DRAW);
  int stride = 0;
  for (int size : sizes) stride += size;
  int offset = 0, index = 0;
  for (int size : sizes) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index++, size, GL_FLOAT, GL_FALSE, stride * static_cast<GLsizei>(sizeof(float)),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    offset += size;
  }
  for (; index < 4; ++index) glDisableVertexAttribArray(index);   // the most a kind of vertex has
}

void StreamedDrawing::AddLines(const scene::LineSet& lines, const Eigen::Matrix4d& PV, const Eigen::Vector3d& eye) {
  const unsigned mode = lines.width > 0 ? GL_TRIANGLES : GL_LINES;
  if (queued_glyphs_ || mode != queued_mode_ || PV != queued_matrix_) Flush();
  queued_mode_ = mode, queued_matrix_ = PV;
  if (lines.width > 0) {
    AppendRibbon(lines, eye, queued_);
  } else {
    // whole pairs only, as a draw of its own drops an odd last point
    for (size_t i = 0; i + 1 < lines.points.size(); i += 2) {
      AppendVertex(lines.points[i], PointColour(lines, i), queued_);
      AppendVertex(lines.points[i + 1], PointColour(lines, i + 1), queued_);
    }
  }
}

void StreamedDrawing::AddTriangles(const scene::FlatTriangles& triangles, const Eigen::Matrix4d& PV) {
  if (queued_glyphs_ || queued_mode_ != GL_TRIANGLES || PV != queued_matrix_) Flush();
  queued_mode_ = GL_TRIANGLES, queued_matrix_ = PV;
  for (size_t i = 0; i < triangles.positions.size() / 3 * 3; ++i) {   // whole triangles, as above
    AppendVertex(triangles.positions[i], triangles.colours[i], queued_);
  }
}

void StreamedDrawing::Flush() {
  if (!queued_.empty() && queued_glyphs_) {
    DrawQueuedLabels();
  } else if (!queued_.empty()) {
    line_.Use();
    line_.Set("model_view_projection", Eigen::Matrix4f(queued_matrix_.cast<float>()));
    Stream(queued_, {3, 4});
    glDisable(GL_CULL_FACE);   // ribbons face the camera; triangle_list_marker.cpp: CULL_NONE
    glDrawArrays(queued_mode_, 0, static_cast<GLsizei>(queued_.size() / 7));
    glEnable(GL_CULL_FACE);
  }
  queued_.clear();
  queued_mode_ = kNothingQueued;
  queued_glyphs_ = nullptr;
}

void StreamedDrawing::AddLabel(const scene::TextLabel& label, const GpuTexture& glyphs, const Eigen::Matrix4d& V,
                               const Eigen::Matrix4d& P) {
  if (queued_glyphs_ != &glyphs || P != queued_matrix_) Flush();
  queued_glyphs_ = &glyphs, queued_mode_ = GL_TRIANGLES, queued_matrix_ = P;
  const Eigen::Vector3f anchor_view = (V * label.anchor.homogeneous()).head<3>().cast<float>();
  for (const auto& q : label.quads) {
    const float corners[6][4] = {
        {q.min.x(), q.max.y(), q.uv_min.x(), q.uv_max.y()},   // upper left
        {q.min.x(), q.min.y(), q.uv_min.x(), q.uv_min.y()},   // lower left
        {q.max.x(), q.max.y(), q.uv_max.x(), q.uv_max.y()},   // upper right
        {q.max.x(), q.max.y(), q.uv_max.x(), q.uv_max.y()},   // upper right
        {q.min.x(), q.min.y(), q.uv_min.x(), q.uv_min.y()},   // lower left
        {q.max.x(), q.min.y(), q.uv_max.x(), q.uv_min.y()}};  // lower right
    for (const auto& corner : corners) {
      queued_.insert(queued_.end(), corner, corner + 4);
      queued_.insert(queued_.end(), anchor_view.data(), anchor_view.data() + 3);
      queued_.insert(queued_.end(), label.rgba.data(), label.rgba.data() + 4);
    }
  }
}

// movable_text.cpp: depth-checked, no depth write, depth bias (1, 1), which Ogre's GL render
// system applies as glPolygonOffset(-1, -1); two triangles per character, as MovableText's
void StreamedDrawing::DrawQueuedLabels() {
  const ShaderProgram& text = text_.Get();
  text.Use();
  text.Set("projection", Eigen::Matrix4f(queued_matrix_.cast<float>()));
  text.Set("glyphs", 0);
  queued_glyphs_->Bind(0);
  Stream(queued_, {2, 2, 3, 4});
  glFrontFace(GL_CCW);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.f, -1.f);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(queued_.size() / 11));
  glDisable(GL_POLYGON_OFFSET_FILL);
}

}  // namespace urdfsnap::gl
