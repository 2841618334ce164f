// OpenGL drawing of a scene::Scene: state setup, draw order and per-item uniforms.
#include "gl/scene_renderer.h"

#include <algorithm>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "common/error.h"
#include "gl/internal/framebuffer.h"
#include "gl/internal/gl_api.h"
#include "gl/gl_context.h"
#include "gl/internal/gpu_mesh.h"
#include "gl/internal/gpu_texture.h"
#include "gl/internal/mesh_batches.h"
#include "gl/internal/point_set_drawing.h"
#include "gl/internal/shader_program.h"

namespace urdfsnap::gl {

namespace {

// Below this alpha Ogre (and so RViz) switches a material to blended, depth-write-off rendering
// (robot_link.cpp L383-430, grid.cpp L115-130).
constexpr float kOpaqueAlpha = 0.9998f;

// Most texture units applied to one mesh. Mesa's fixed-function pipeline has 8; Ogre splits a
// pass with more into several multiplying passes, which comes to the same product, but a hostile
// mesh file could ask for millions.
constexpr int kMaxTextureUnits = 32;

struct Transparent {
  double depth;            // squared distance from the eye, for back-to-front order
  std::variant<const scene::DrawItem*, const scene::LineSet*, const scene::TextLabel*, const scene::PointSet*,
               const scene::FlatTriangles*>
      what;
};

// GPU copies of scene data, made on first use and kept while the source object lives: entries
// hold the source weakly and are dropped (their GPU memory freed) once it is gone, so a renderer
// that draws many robots or reloaded models does not grow. Keyed by the source's address; an
// entry whose source died is replaced when a new object reuses the address.
template <typename Source, typename Gpu>
class GpuCache {
 public:
  const Gpu& Get(const std::shared_ptr<const Source>& source) {
    auto it = entries_.find(source.get());
    if (it == entries_.end() || it->second.source.expired()) {
      if (entries_.size() >= purge_at_) Purge();
      it = entries_.insert_or_assign(source.get(), Entry{source, std::make_unique<Gpu>(*source)}).first;
    }
    return *it->second.gpu;
  }

 private:
  struct Entry {
    std::weak_ptr<const Source> source;
    std::unique_ptr<Gpu> gpu;
  };
  void Purge() {
    std::erase_if(entries_, [](const auto& entry) { return entry.second.source.expired(); });
    purge_at_ = std::max<size_t>(64, 2 * entries_.size());
  }
  std::unordered_map<const Source*, Entry> entries_;
  size_t purge_at_ = 64;
};

// Appends one vertex of the line shader: position, then rgba.
void AppendVertex(const Eigen::Vector3f& p, const Eigen::Vector4f& rgba, std::vector<float>& floats) {
  floats.insert(floats.end(), p.data(), p.data() + 3);
  floats.insert(floats.end(), rgba.data(), rgba.data() + 4);
}

Eigen::Vector4f PointColour(const scene::LineSet& lines, size_t i) {
  return i < lines.colours.size() ? lines.colours[i] : lines.rgba;
}

std::vector<float> LineVertices(const scene::LineSet& lines) {
  std::vector<float> floats;
  floats.reserve(lines.points.size() * 7);
  for (size_t i = 0; i < lines.points.size(); ++i) AppendVertex(lines.points[i], PointColour(lines, i), floats);
  return floats;
}

// billboard_line.cpp: each segment a quad `width` wide, its sides offset from the segment by half
// the width along the direction across both the segment and the line of sight from `eye`.
std::vector<float> RibbonVertices(const scene::LineSet& lines, const Eigen::Vector3d& eye) {
  std::vector<float> floats;
  floats.reserve(lines.points.size() / 2 * 6 * 7);
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
  return floats;
}

// Whether every colour of `set` (a PointSet, FlatTriangles) is opaque: RViz's point cloud blends
// (without depth writes) once its alpha or any point's is below 1 (point_cloud.cpp,
// PointCloud::setAlpha), and so does a triangle list whose alpha is (triangle_list_marker.cpp).
template <typename Set>
bool Opaque(const Set& set) {
  return std::all_of(set.colours.begin(), set.colours.end(),
                     [](const Eigen::Vector4f& rgba) { return rgba.w() >= kOpaqueAlpha; });
}

// The mean of `points`, where a set of them is sorted among the transparent objects.
template <typename Points>
Eigen::Vector3d Centre(const Points& points) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : points) centre += p.template cast<double>();
  if (!points.empty()) centre /= static_cast<double>(points.size());
  return centre;
}

}  // namespace

struct SceneRenderer::Impl {
  Impl(int samples, const BackendChoice& backend)
      : samples(samples),
        context(CreateGlContext(backend.backend, backend.asked_by)),
        lit("lit.vert", "lit.frag"),
        line("line.vert", "line.frag") {
    glGenVertexArrays(1, &stream_array);
    glGenBuffers(1, &stream_buffer);
    glGenBuffers(1, &instance_buffer);
  }
  ~Impl() {
    // this context's objects are deleted in it (the members below too), not in whichever
    // context another SceneRenderer made current last
    try {
      context->MakeCurrent();
    } catch (const Error&) {
      // nothing to delete them in: they go with the context
    }
    glDeleteBuffers(1, &instance_buffer);
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

  // Draws the instances of `batch` with the lit program, textured when its items are.
  void DrawBatch(const MeshBatch& batch) {
    const ShaderProgram& program = batch.key.texture_units > 0 ? lit_textured.Get() : lit;
    program.Use();
    if (batch.key.texture_units > 0) {
      program.Set("texture_units", batch.key.texture_units);
      program.Set("image", 0);
      textures.Get(batch.item->texture).Bind(0);
    }
    // a mirroring scale turns the winding around; Ogre flips culling for such nodes, and so do we
    glFrontFace(batch.key.mirrored ? GL_CW : GL_CCW);
    glBindBuffer(GL_ARRAY_BUFFER, instance_buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(batch.instances.size() * sizeof(MeshInstance)),
                 batch.instances.data(), GL_STREAM_DRAW);
    batch.mesh->DrawInstances(instance_buffer, static_cast<int>(batch.instances.size()));
  }

  // Draws the batches of `batches` in order and empties it.
  void DrawBatches(MeshBatches& batches) {
    for (const MeshBatch& batch : batches.batches()) DrawBatch(batch);
    batches.Clear();
  }

  // 1-pixel lines, or with a width the camera-facing ribbons of RibbonVertices
  void DrawLines(const scene::LineSet& lines, const Eigen::Matrix4d& PV, const Eigen::Vector3d& eye) {
    line.Use();
    line.Set("model_view_projection", Eigen::Matrix4f(PV.cast<float>()));
    const std::vector<float> floats = lines.width > 0 ? RibbonVertices(lines, eye) : LineVertices(lines);
    Stream(floats, {3, 4});
    glDisable(GL_CULL_FACE);
    glDrawArrays(lines.width > 0 ? GL_TRIANGLES : GL_LINES, 0, static_cast<GLsizei>(floats.size() / 7));
    glEnable(GL_CULL_FACE);
  }

  void DrawTriangles(const scene::FlatTriangles& triangles, const Eigen::Matrix4d& PV) {
    line.Use();
    line.Set("model_view_projection", Eigen::Matrix4f(PV.cast<float>()));
    std::vector<float> floats;
    floats.reserve(triangles.positions.size() * 7);
    for (size_t i = 0; i < triangles.positions.size(); ++i) {
      AppendVertex(triangles.positions[i], triangles.colours[i], floats);
    }
    Stream(floats, {3, 4});
    glDisable(GL_CULL_FACE);   // triangle_list_marker.cpp: CULL_NONE
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangles.positions.size()));
    glEnable(GL_CULL_FACE);
  }

  // movable_text.cpp: depth-checked, no depth write, depth bias (1, 1), which Ogre's GL render
  // system applies as glPolygonOffset(-1, -1); two triangles per character, as MovableText's
  void DrawLabel(const scene::TextLabel& label, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P) {
    if (label.quads.empty()) return;
    const ShaderProgram& text = this->text.Get();
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

  // The colour image: opaque geometry first, then transparent geometry, lines and text blended
  // back to front, as Ogre orders RViz's scene.
  image::Image DrawColour(const scene::Scene& scene, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P,
                          int width, int height) {
    ClearColourFramebuffer(scene.background, width, height);
    const Eigen::Vector3d eye = V.inverse().topRightCorner<3, 1>();
    DrawBlended(DrawOpaque(scene, V, P, eye), V, P, eye);
    return framebuffer->ReadPixels();
  }

  // Binds the colour framebuffer (made anew for another size) cleared to `background`, depth-tested
  // and back faces culled.
  void ClearColourFramebuffer(const Eigen::Vector3f& background, int width, int height) {
    if (!framebuffer || framebuffer->width() != width || framebuffer->height() != height) {
      framebuffer.reset();
      framebuffer = std::make_unique<Framebuffer>(width, height, samples);
    }
    framebuffer->Bind();
    glClearColor(background.x(), background.y(), background.z(), 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
  }

  // Draws the opaque meshes, point sets and triangles, writing depth; returns the rest (transparent
  // ones, every line set and label) with their squared distances from `eye`, back to front.
  std::vector<Transparent> DrawOpaque(const scene::Scene& scene, const Eigen::Matrix4d& V,
                                      const Eigen::Matrix4d& P, const Eigen::Vector3d& eye) {
    const Eigen::Matrix4d PV = P * V;
    glDisable(GL_BLEND);
    std::vector<Transparent> transparent;
    for (const auto& item : scene.items) {
      if (item.rgba.w() >= kOpaqueAlpha) {
        batches.Add(item, meshes.Get(item.mesh), kMaxTextureUnits, V, PV, MeshBatches::Join::kAny);
      } else {
        transparent.push_back({(item.X_FG.translation() - eye).squaredNorm(), &item});
      }
    }
    DrawBatches(batches);
    std::vector<const scene::PointSet*> opaque_points;
    for (const auto& points : scene.points) {
      if (Opaque(points)) {
        opaque_points.push_back(&points);
      } else {
        transparent.push_back({(Centre(points.positions) - eye).squaredNorm(), &points});
      }
    }
    point_sets().DrawOpaque(opaque_points, V, P);
    for (const auto& triangles : scene.triangles) {
      if (Opaque(triangles)) {
        DrawTriangles(triangles, PV);
      } else {
        transparent.push_back({(Centre(triangles.positions) - eye).squaredNorm(), &triangles});
      }
    }
    for (const auto& lines : scene.lines) {
      transparent.push_back({(Centre(lines.points) - eye).squaredNorm(), &lines});
    }
    // Ogre sorts MovableText with the transparent objects by its node's position, the anchor
    for (const auto& text_label : scene.labels) {
      transparent.push_back({(text_label.anchor - eye).squaredNorm(), &text_label});
    }
    // Ogre's transparent queue (OgreRenderQueueSortingGrouping.cpp, QueuedRenderableCollection::sort
    // with OM_SORT_DESCENDING): stably sorted far to near by each renderable's squared view depth,
    // which for an entity's sub-meshes is its scene node's distance from the camera
    // (OgreSubEntity.cpp, getSquaredViewDepth): a marker's pose, a robot link's visual origin
    std::stable_sort(transparent.begin(), transparent.end(),
                     [](const Transparent& a, const Transparent& b) { return a.depth > b.depth; });
    return transparent;
  }

  // Draws `transparent` in its order, blended, depth-tested but not writing depth. Neighbours in
  // that order with the same mesh are one instanced draw, which blends its instances in order.
  void DrawBlended(const std::vector<Transparent>& transparent, const Eigen::Matrix4d& V,
                   const Eigen::Matrix4d& P, const Eigen::Vector3d& eye) {
    const Eigen::Matrix4d PV = P * V;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (const auto& t : transparent) {
      if (const auto* item = std::get_if<const scene::DrawItem*>(&t.what)) {
        batches.Add(**item, meshes.Get((*item)->mesh), kMaxTextureUnits, V, PV, MeshBatches::Join::kLast);
        continue;
      }
      DrawBatches(batches);
      if (const auto* lines = std::get_if<const scene::LineSet*>(&t.what)) {
        DrawLines(**lines, PV, eye);
      } else if (const auto* points = std::get_if<const scene::PointSet*>(&t.what)) {
        point_sets().Draw(**points, V, P);
      } else if (const auto* triangles = std::get_if<const scene::FlatTriangles*>(&t.what)) {
        DrawTriangles(**triangles, PV);
      } else {
        DrawLabel(*std::get<const scene::TextLabel*>(t.what), V, P);
      }
    }
    DrawBatches(batches);
    glDepthMask(GL_TRUE);
  }

  // The label image (the depths stay in the label framebuffer for ReadDepths): every draw item
  // with a link, opaque or not, depth-tested and depth-writing, culled as in the colour image.
  image::LabelImage DrawLabels(const scene::Scene& scene, const Eigen::Matrix4d& V,
                               const Eigen::Matrix4d& P, int width, int height) {
    if (!label_framebuffer || label_framebuffer->width() != width || label_framebuffer->height() != height) {
      label_framebuffer.reset();
      label_framebuffer = std::make_unique<LabelFramebuffer>(width, height);
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    label_framebuffer->BindAndClear();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    const ShaderProgram& label = this->label.Get();
    label.Use();
    label.Set("projection", Eigen::Matrix4f(P.cast<float>()));
    for (const auto& item : scene.items) {
      if (item.link < 0) continue;
      if (item.link >= 0xFFFF) {
        throw Error("the label image holds 65534 links; link index " + std::to_string(item.link) + " does not fit");
      }
      const Eigen::Matrix4d M = item.X_FG.matrix();
      const GpuMesh& mesh = meshes.Get(item.mesh);
      if (mesh.OutsideClipVolume(P * V * M)) continue;
      label.Set("model_view", Eigen::Matrix4f((V * M).cast<float>()));
      label.Set("label", static_cast<unsigned>(item.link + 1));
      glFrontFace(M.topLeftCorner<3, 3>().determinant() < 0 ? GL_CW : GL_CCW);
      mesh.Draw();
    }
    return label_framebuffer->ReadLabels();
  }

  int samples;
  std::unique_ptr<GlContext> context;
  ShaderProgram lit;                           // untextured surfaces
  LazyShaderProgram lit_textured{"lit.vert", "lit.frag", "TEXTURED"};   // and textured ones
  ShaderProgram line;
  LazyShaderProgram text{"text.vert", "text.frag"};
  LazyShaderProgram label{"label.vert", "label.frag"};
  // the point programs, made for the first point set drawn
  std::optional<PointSetDrawing> point_sets_made;
  PointSetDrawing& point_sets() {
    if (!point_sets_made) point_sets_made.emplace();
    return *point_sets_made;
  }
  unsigned stream_array = 0, stream_buffer = 0;   // per-frame vertices: lines and text
  unsigned instance_buffer = 0;                    // per-draw MeshInstances
  MeshBatches batches;                             // the lit meshes of the draw being gathered
  std::unique_ptr<Framebuffer> framebuffer;
  std::unique_ptr<LabelFramebuffer> label_framebuffer;
  GpuCache<geometry::TriangleMesh, GpuMesh> meshes;
  GpuCache<texture::TextureImage, GpuTexture> textures;
};

SceneRenderer::SceneRenderer(int samples, const BackendChoice& backend)
    : impl_(std::make_unique<Impl>(samples, backend)) {
  if (backend.on_context) backend.on_context(Summary());
}

SceneRenderer::~SceneRenderer() = default;

Backend SceneRenderer::backend() const { return impl_->context->backend(); }

const std::string& SceneRenderer::description() const { return impl_->context->description(); }

std::string SceneRenderer::Summary() const { return impl_->context->Summary(); }

void SceneRenderer::ReleaseContext() { impl_->context->Release(); }

image::Frame SceneRenderer::Render(const scene::Scene& scene, const scene::OrbitView& view, int width,
                              int height, const image::FrameOutputs& outputs) {
  return Render(scene, scene::ViewMatrix(view), scene::ProjectionMatrix(view, static_cast<double>(width) / height),
                width, height, outputs);
}

image::Frame SceneRenderer::Render(const scene::Scene& scene, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P,
                              int width, int height, const image::FrameOutputs& outputs) {
  Impl& r = *impl_;
  r.context->MakeCurrent();
  image::Frame frame;
  if (outputs.colour) frame.colour = r.DrawColour(scene, V, P, width, height);
  if (outputs.depth || outputs.labels) {
    image::LabelImage labels = r.DrawLabels(scene, V, P, width, height);
    if (outputs.depth) frame.depth = r.label_framebuffer->ReadDepths(labels);
    if (outputs.labels) frame.labels = std::move(labels);
  }
  return frame;
}

}  // namespace urdfsnap::gl
