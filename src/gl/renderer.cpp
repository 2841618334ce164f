// OpenGL drawing of a scene::Scene: state setup, draw order and per-item uniforms.
#include "gl/renderer.h"

#include <algorithm>
#include <unordered_map>
#include <variant>
#include <vector>

#include "gl/framebuffer.h"
#include "gl/gl_api.h"
#include "gl/gl_context.h"
#include "gl/gpu_mesh.h"
#include "gl/gpu_texture.h"
#include "gl/shader_program.h"

namespace urdfsnap::gl {

namespace {

// Below this alpha Ogre (and so RViz) switches a material to blended, depth-write-off rendering
// (robot_link.cpp L383-430, grid.cpp L115-130).
constexpr float kOpaqueAlpha = 0.9998f;

struct Transparent {
  double depth;            // squared distance from the eye, for back-to-front order
  std::variant<const scene::DrawItem*, const scene::LineSet*, const scene::TextLabel*> what;
};

// GPU copies of scene data, made on first use and kept for later frames. Keyed by the source's
// address; the shared_ptr kept beside each copy keeps that address from being reused.
template <typename Source, typename Gpu>
class GpuCache {
 public:
  const Gpu& Get(const std::shared_ptr<const Source>& source) {
    auto it = entries_.find(source.get());
    if (it == entries_.end()) {
      it = entries_.try_emplace(source.get(), source, std::make_unique<Gpu>(*source)).first;
    }
    return *it->second.second;
  }

 private:
  std::unordered_map<const Source*, std::pair<std::shared_ptr<const Source>, std::unique_ptr<Gpu>>> entries_;
};

}  // namespace

struct Renderer::Impl {
  explicit Impl(int samples)
      : samples(samples),
        context(CreateOsMesaContext()),
        lit("lit.vert", "lit.frag"),
        line("line.vert", "line.frag"),
        text("text.vert", "text.frag") {
    glGenVertexArrays(1, &stream_array);
    glGenBuffers(1, &stream_buffer);
  }
  ~Impl() {
    glDeleteBuffers(1, &stream_buffer);
    glDeleteVertexArrays(1, &stream_array);
  }

  // Fills the stream buffer with `floats` and sets up attribute i from `sizes[i]` of each vertex.
  void Stream(const std::vector<float>& floats, std::initializer_list<int> sizes) {
    glBindVertexArray(stream_array);
    glBindBuffer(GL_ARRAY_BUFFER, stream_buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(floats.size() * sizeof(float)),
                 floats.data(), GL_STREAM_DRAW);
    int stride = 0;
    for (int size : sizes) stride += size;
    int offset = 0, index = 0;
    for (int size : sizes) {
      glEnableVertexAttribArray(index);
      glVertexAttribPointer(index++, size, GL_FLOAT, GL_FALSE, stride * static_cast<GLsizei>(sizeof(float)),
                            reinterpret_cast<const void*>(offset * sizeof(float)));
      offset += size;
    }
    for (; index < 2; ++index) glDisableVertexAttribArray(index);
  }

  void DrawMesh(const scene::DrawItem& item, const Eigen::Matrix4d& V, const Eigen::Matrix4d& PV) {
    const Eigen::Matrix4d M = item.X_FG.matrix();
    lit.Set("model_view_projection", Eigen::Matrix4f((PV * M).cast<float>()));
    const Eigen::Matrix3d MV = (V * M).topLeftCorner<3, 3>();
    lit.Set("normal_to_view", Eigen::Matrix3f(MV.inverse().transpose().cast<float>()));
    lit.Set("diffuse", item.rgba);
    lit.Set("emissive", item.emissive);
    lit.Set("textured", item.texture ? 1 : 0);
    if (item.texture) {
      lit.Set("image", 0);
      textures.Get(item.texture).Bind(0);
    }
    // a mirroring scale turns the winding around; Ogre flips culling for such nodes, and so do we
    glFrontFace(M.topLeftCorner<3, 3>().determinant() < 0 ? GL_CW : GL_CCW);
    meshes.Get(item.mesh).Draw();
  }

  void DrawLines(const scene::LineSet& lines, const Eigen::Matrix4d& PV) {
    line.Use();
    line.Set("model_view_projection", Eigen::Matrix4f(PV.cast<float>()));
    line.Set("colour", lines.rgba);
    std::vector<float> floats;
    floats.reserve(lines.points.size() * 3);
    for (const auto& p : lines.points) floats.insert(floats.end(), p.data(), p.data() + 3);
    Stream(floats, {3});
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.points.size()));
  }

  // movable_text.cpp: depth-checked, no depth write, depth bias (1, 1), which Ogre's GL render
  // system applies as glPolygonOffset(-1, -1); two triangles per character, as MovableText's
  void DrawLabel(const scene::TextLabel& label, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P) {
    if (label.quads.empty()) return;
    text.Use();
    text.Set("projection", Eigen::Matrix4f(P.cast<float>()));
    text.Set("anchor_view", Eigen::Vector3f((V * label.anchor.homogeneous()).head<3>().cast<float>()));
    text.Set("colour", label.rgba);
    text.Set("glyphs", 0);
    textures.Get(label.texture).Bind(0);
    std::vector<float> floats;
    floats.reserve(label.quads.size() * 24);
    for (const auto& q : label.quads) {
      const float corners[6][4] = {
          {q.min.x(), q.max.y(), q.uv_min.x(), q.uv_max.y()},   // upper left
          {q.min.x(), q.min.y(), q.uv_min.x(), q.uv_min.y()},   // lower left
          {q.max.x(), q.max.y(), q.uv_max.x(), q.uv_max.y()},   // upper right
          {q.max.x(), q.max.y(), q.uv_max.x(), q.uv_max.y()},   // upper right
          {q.min.x(), q.min.y(), q.uv_min.x(), q.uv_min.y()},   // lower left
          {q.max.x(), q.min.y(), q.uv_max.x(), q.uv_min.y()}};  // lower right
      for (const auto& corner : corners) floats.insert(floats.end(), corner, corner + 4);
    }
    Stream(floats, {2, 2});
    glFrontFace(GL_CCW);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.f, -1.f);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(label.quads.size() * 6));
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  int samples;
  std::unique_ptr<GlContext> context;
  ShaderProgram lit;
  ShaderProgram line;
  ShaderProgram text;
  unsigned stream_array = 0, stream_buffer = 0;   // per-frame vertices: lines and text
  std::unique_ptr<Framebuffer> framebuffer;
  GpuCache<geometry::TriangleMesh, GpuMesh> meshes;
  GpuCache<scene::TextureImage, GpuTexture> textures;
};

Renderer::Renderer(int samples) : impl_(std::make_unique<Impl>(samples)) {}

Renderer::~Renderer() = default;

image::Image Renderer::Render(const scene::Scene& scene, const scene::OrbitView& view, int width, int height) {
  Impl& r = *impl_;
  r.context->MakeCurrent();
  if (!r.framebuffer || r.framebuffer->width() != width || r.framebuffer->height() != height) {
    r.framebuffer.reset();
    r.framebuffer = std::make_unique<Framebuffer>(width, height, r.samples);
  }
  r.framebuffer->Bind();

  const Eigen::Matrix4d V = scene::ViewMatrix(view);
  const Eigen::Matrix4d P = scene::ProjectionMatrix(view, static_cast<double>(width) / height);
  const Eigen::Matrix4d PV = P * V;
  const Eigen::Vector3d eye = scene::EyePosition(view);

  glClearColor(scene.background.x(), scene.background.y(), scene.background.z(), 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);

  // opaque geometry first, writing depth
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  r.lit.Use();
  std::vector<Transparent> transparent;
  for (const auto& item : scene.items) {
    if (item.rgba.w() >= kOpaqueAlpha) {
      r.DrawMesh(item, V, PV);
    } else {
      transparent.push_back({(item.X_FG.translation() - eye).squaredNorm(), &item});
    }
  }
  for (const auto& lines : scene.lines) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : lines.points) centre += p.cast<double>();
    if (!lines.points.empty()) centre /= static_cast<double>(lines.points.size());
    transparent.push_back({(centre - eye).squaredNorm(), &lines});
  }
  // Ogre sorts MovableText with the transparent objects by its node's position, the anchor
  for (const auto& label : scene.labels) {
    transparent.push_back({(label.anchor - eye).squaredNorm(), &label});
  }

  // then blended geometry back to front, depth-tested but not writing depth
  std::stable_sort(transparent.begin(), transparent.end(),
                   [](const Transparent& a, const Transparent& b) { return a.depth > b.depth; });
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  for (const auto& t : transparent) {
    if (const auto* item = std::get_if<const scene::DrawItem*>(&t.what)) {
      r.lit.Use();
      r.DrawMesh(**item, V, PV);
    } else if (const auto* lines = std::get_if<const scene::LineSet*>(&t.what)) {
      r.DrawLines(**lines, PV);
    } else {
      r.DrawLabel(*std::get<const scene::TextLabel*>(t.what), V, P);
    }
  }
  glDepthMask(GL_TRUE);
  return r.framebuffer->ReadPixels();
}

}  // namespace urdfsnap::gl
