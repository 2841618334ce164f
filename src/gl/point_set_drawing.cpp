// Batches of points into GL: position and 8-bit rgba per vertex, a vertex per GL point and per
// corner of a square or box (which corner from gl_VertexID).
#include "gl/internal/point_set_drawing.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "gl/internal/gl_api.h"

namespace urdfsnap::gl {

namespace {

// One vertex: position in the fixed frame and colour, 16 bytes.
struct PointVertex {
  float position[3];
  std::uint8_t rgba[4];
};
static_assert(sizeof(PointVertex) == 16);

// Vertices per draw call: a batch streams at most this many (4 MiB), so the GPU memory stays bounded.
constexpr size_t kBatchVertices = 262144;

// A square's corners in strip order, drawn as two triangles (0, 1, 2) and (2, 1, 3); a box is six
// such faces (shaders/point_box.vert).
constexpr std::uint32_t kQuadIndices[6] = {0, 1, 2, 2, 1, 3};

std::uint8_t Channel(float value) {
  return static_cast<std::uint8_t>(std::clamp(value, 0.f, 1.f) * 255.f + 0.5f);
}

// The points of `points` drawn: those with both a position and a colour.
size_t Count(const scene::PointSet& points) { return std::min(points.positions.size(), points.colours.size()); }

// Whether `a` and `b` draw with the same program and uniforms, and so as one draw.
bool SameLook(const scene::PointSet& a, const scene::PointSet& b) {
  return a.style == b.style && a.size == b.size && a.box_axes == b.box_axes;
}

}  // namespace

PointSetDrawing::PointSetDrawing()
    : point_("point.vert", "point.frag"),
      quad_("point_quad.vert", "point.frag"),
      box_("point_box.vert", "point.frag"),
      splat_program_("point_splat.vert", "point_splat.frag") {
  glGenVertexArrays(1, &splat_array_);
  glBindVertexArray(splat_array_);
  glGenBuffers(1, &splat_corners_);
  glBindBuffer(GL_ARRAY_BUFFER, splat_corners_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glGenTextures(1, &splat_texture_);
  glGenVertexArrays(1, &vertex_array_);
  glBindVertexArray(vertex_array_);
  glGenBuffers(2, buffers_);
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(PointVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(PointVertex),
                        reinterpret_cast<const void*>(offsetof(PointVertex, rgba)));
  glBindVertexArray(0);
}

// Makes the index buffer hold the triangles of at least `quads` squares of four vertices each,
// square q's corners being vertices 4q to 4q + 3.
void PointSetDrawing::HoldQuads(size_t quads) {
  if (quads <= quads_held_) return;
  std::vector<std::uint32_t> indices;
  indices.reserve(quads * std::size(kQuadIndices));
  for (std::uint32_t q = 0; q < quads; ++q) {
    for (std::uint32_t i : kQuadIndices) indices.push_back(4 * q + i);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
               indices.data(), GL_STATIC_DRAW);
  quads_held_ = quads;
}

PointSetDrawing::~PointSetDrawing() {
  if (splat_read_ != nullptr) glDeleteSync(splat_read_);
  glDeleteBuffers(1, &splat_buffer_);   // unmapped as it goes
  glDeleteTextures(1, &splat_texture_);
  glDeleteBuffers(1, &splat_corners_);
  glDeleteVertexArrays(1, &splat_array_);
  glDeleteBuffers(2, buffers_);
  glDeleteVertexArrays(1, &vertex_array_);
}

// Streams the next `count` points of `sets` from `cursor` on, `copies` vertices each, moving the
// cursor past them.
void PointSetDrawing::Upload(std::span<const scene::PointSet* const> sets, Cursor& cursor, size_t count,
                             size_t copies) {
  staging_.resize(count * copies * sizeof(PointVertex));
  auto* out = reinterpret_cast<PointVertex*>(staging_.data());
  for (size_t left = count; left > 0;) {
    const scene::PointSet& points = *sets[cursor.set];
    const size_t n = std::min(Count(points) - cursor.point, left);
    for (size_t i = cursor.point; i < cursor.point + n; ++i) {
      const Eigen::Vector3f& p = points.positions[i];
      const Eigen::Vector4f& c = points.colours[i];
      const PointVertex vertex{{p.x(), p.y(), p.z()}, {Channel(c[0]), Channel(c[1]), Channel(c[2]), Channel(c[3])}};
      out = std::fill_n(out, copies, vertex);
    }
    left -= n, cursor.point += n;
    if (cursor.point == Count(points)) cursor = {cursor.set + 1, 0};
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(staging_.size()), staging_.data(), GL_STREAM_DRAW);
}

void PointSetDrawing::Draw(const scene::PointSet& points, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P) {
  const scene::PointSet* const one[] = {&points};
  Draw(one, V, P);
}

void PointSetDrawing::Draw(std::span<const scene::PointSet* const> sets, const Eigen::Matrix4d& V,
                           const Eigen::Matrix4d& P) {
  using Style = scene::PointSet::Style;
  size_t n = 0;
  for (const scene::PointSet* points : sets) n += Count(*points);
  if (n == 0) return;
  const scene::PointSet& points = *sets.front();   // the style and sizes of them all
  const Eigen::Matrix4f MVP = (P * V).cast<float>();
  const ShaderProgram* program = &quad_;
  size_t quads = 1;   // squares drawn per point, of four vertices each; 0 for GL points, one vertex each
  int shape = 0;      // point.frag's: 0 flat, 1 outlined square, 2 shaded disc
  switch (points.style) {
    case Style::kPoints:
      program = &point_;
      quads = 0;
      break;
    case Style::kSquares: shape = 1; break;
    case Style::kFlatSquares: break;
    case Style::kSpheres: shape = 2; break;
    case Style::kBoxes:
      program = &box_;
      quads = 6;
      shape = 1;
      break;
  }
  program->Use();
  if (program != &point_) program->Set("shape", shape);   // points: 0, the default (flat)
  if (program == &point_) {
    point_.Set("model_view_projection", MVP);
    point_.Set("point_size", std::max(points.size.x(), 1.f));
    glEnable(GL_PROGRAM_POINT_SIZE);
  } else if (program == &quad_) {
    quad_.Set("model_view", Eigen::Matrix4f(V.cast<float>()));
    quad_.Set("projection", Eigen::Matrix4f(P.cast<float>()));
    quad_.Set("size", points.size.x());
  } else {
    box_.Set("model_view_projection", MVP);
    box_.Set("size", points.size);
    box_.Set("axes", points.box_axes);
  }
  // boxes wind counter-clockwise seen from outside and lose their far faces to culling, as Ogre's
  // default culling does; a camera-facing square needs none
  if (points.style == Style::kBoxes) {
    glFrontFace(GL_CCW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  glBindVertexArray(vertex_array_);
  // squares and boxes: each point's vertex copied to its corners (gl_VertexID tells them apart),
  // rather than an instance per point, which llvmpipe's vertex stage runs as a draw of its own
  const size_t copies = std::max<size_t>(4 * quads, 1), batch = kBatchVertices / copies;
  if (quads > 0) HoldQuads(std::min(n, batch) * quads);
  Cursor cursor;
  for (size_t first = 0; first < n; first += batch) {
    const size_t count = std::min(batch, n - first);
    Upload(sets, cursor, count, copies);
    if (quads == 0) {
      glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
    } else {
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count * quads * std::size(kQuadIndices)), GL_UNSIGNED_INT,
                     nullptr);
    }
  }
  glDisable(GL_PROGRAM_POINT_SIZE);
  glEnable(GL_CULL_FACE);
}

void PointSetDrawing::DrawOpaque(const std::vector<const scene::PointSet*>& sets, const Eigen::Matrix4d& V,
                                 const Eigen::Matrix4d& P) {
  // the bound framebuffer's size and sample positions
  GLint viewport[4] = {0, 0, 0, 0}, samples = 0, max_texels = 0;
  glGetIntegerv(GL_VIEWPORT, viewport);
  glGetIntegerv(GL_SAMPLES, &samples);
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  // the splat's texels are a buffer texture of a pair for each sample of each pixel of the tiles
  // (Composite): more than GL allows (or no buffer to be mapped), the sets are drawn by GL; and
  // points that GL draws for less than kFewestPoints squares are drawn by GL too (cheaper; the
  // same pixels)
  std::size_t splattable = 0;
  for (const scene::PointSet* points : sets) {
    if (PointSplat::Splattable(*points)) splattable += PointSplat::GlCost(*points);
  }
  const std::size_t words = PointSplat::TexelWords(viewport[2], viewport[3], std::max(samples, 1));
  std::uint32_t* const texels = splattable >= PointSplat::kFewestPoints && words / 2 <= static_cast<std::size_t>(max_texels)
                                    ? SplatTexels(words)
                                    : nullptr;
  const bool can_splat = texels != nullptr;
  bool splatting = false;
  // the sets GL draws, those of one look as one draw (opaque sets' order decides only between
  // fragments at equal depths, which Ogre's opaque queue, sorted by material, leaves open too)
  std::vector<std::vector<const scene::PointSet*>> looks;
  for (const scene::PointSet* points : sets) {
    if (!can_splat || !PointSplat::Splattable(*points)) {
      const auto same =
          std::find_if(looks.begin(), looks.end(), [&](const auto& look) { return SameLook(*look.front(), *points); });
      if (same == looks.end()) {
        looks.push_back({points});
      } else {
        same->push_back(points);
      }
      continue;
    }
    if (!splatting) {
      std::vector<Eigen::Vector2f> positions(std::max(samples, 1), Eigen::Vector2f(0.5f, 0.5f));
      for (GLint s = 0; s < samples; ++s) glGetMultisamplefv(GL_SAMPLE_POSITION, s, positions[s].data());
      splat_.Clear(viewport[2], viewport[3], positions);
      splatting = true;
    }
    splat_.Add(*points, V, P);
  }
  for (const auto& look : looks) Draw(look, V, P);
  if (!splatting) return;
  splat_.Cover(texels);
  if (!splat_.empty()) Composite();
}

std::uint32_t* PointSetDrawing::SplatTexels(std::size_t words) {
  if (splat_read_ != nullptr) {
    // the last frame's composite has read its texels (its read-back waited for it; this makes sure)
    glClientWaitSync(splat_read_, GL_SYNC_FLUSH_COMMANDS_BIT, GL_TIMEOUT_IGNORED);
    glDeleteSync(splat_read_);
    splat_read_ = nullptr;
  }
  if (words > splat_words_) {
    glDeleteBuffers(1, &splat_buffer_);
    glGenBuffers(1, &splat_buffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, splat_buffer_);
    const GLbitfield access = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    const auto bytes = static_cast<GLsizeiptr>(words * sizeof(std::uint32_t));
    glBufferStorage(GL_TEXTURE_BUFFER, bytes, nullptr, access);
    splat_texels_ = static_cast<std::uint32_t*>(glMapBufferRange(GL_TEXTURE_BUFFER, 0, bytes, access));
    splat_words_ = splat_texels_ != nullptr ? words : 0;   // none mapped: the next frame tries again
    glBindTexture(GL_TEXTURE_BUFFER, splat_texture_);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RG32UI, splat_buffer_);
  }
  return splat_texels_;
}

// Draws the drawn tiles' texels, which the splat wrote into the buffer texture, per sample: a
// rectangle over each run of drawn tiles side by side.
void PointSetDrawing::Composite() {
  const int samples = splat_.samples(), width = splat_.width(), height = splat_.height();
  const std::vector<int>& drawn = splat_.drawn();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, splat_texture_);
  // window pixels to clip space; two triangles per run of drawn tiles in a row of tiles
  const auto clip = [](int pixel, int size) { return 2.f * static_cast<float>(pixel) / static_cast<float>(size) - 1.f; };
  std::vector<float> corners;
  for (std::size_t first = 0, last = 0; first < drawn.size(); first = ++last) {
    const PointSplat::Tile tile = splat_.TileAt(drawn[first]);
    while (last + 1 < drawn.size() && drawn[last + 1] == drawn[last] + 1 && splat_.TileAt(drawn[last + 1]).y0 == tile.y0) {
      ++last;
    }
    const float x0 = clip(tile.x0, width), x1 = clip(splat_.TileAt(drawn[last]).x1, width);
    const float y0 = clip(tile.y0, height), y1 = clip(tile.y1, height);
    corners.insert(corners.end(), {x0, y0, x1, y0, x0, y1, x0, y1, x1, y0, x1, y1});
  }
  splat_program_.Use();
  splat_program_.Set("texels", 0);
  splat_program_.Set("samples", samples);
  splat_program_.Set("tile_bits", std::countr_zero(static_cast<unsigned>(PointSplat::kTileSize)));
  splat_program_.Set("tiles_x", splat_.tiles_x());
  glDisable(GL_CULL_FACE);
  glBindVertexArray(splat_array_);
  glBindBuffer(GL_ARRAY_BUFFER, splat_corners_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(float)), corners.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners.size() / 2));
  splat_read_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glBindVertexArray(0);
  glEnable(GL_CULL_FACE);
}

}  // namespace urdfsnap::gl
