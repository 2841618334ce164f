// OpenGL drawing of a scene::Scene: state setup, draw order and per-item uniforms.
#include "gl/scene_renderer.h"

#include <algorithm>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "common/error.h"
#include "gl/internal/coverage_cull.h"
#include "gl/internal/framebuffer.h"
#include "gl/internal/gl_api.h"
#include "gl/gl_context.h"
#include "gl/internal/gpu_mesh.h"
#include "gl/internal/gpu_texture.h"
#include "gl/internal/mesh_batches.h"
#include "gl/internal/point_set_drawing.h"
#include "gl/internal/shader_program.h"
#include "gl/internal/streamed_drawing.h"

namespace urdfsnap::gl {

namespace {

// Below this alpha Ogre (and so RViz) switches a material to blended, depth-write-off rendering
// (robot_link.cpp L383-430, grid.cpp L115-130).
constexpr float kOpaqueAlpha = 0.9998f;

// Most texture units applied to one mesh. Mesa's fixed-function pipeline has 8; Ogre splits a
// pass with more into several multiplying passes, which comes to the same product, but a hostile
// mesh file could ask for millions.
constexpr int kMaxTextureUnits = 32;

// With a triangle per this many pixels or more, the colour pass draws the label and depth images
// too (SceneRenderer::Impl::OneDrawLabels).
constexpr long long kPixelsPerTriangleForOneDraw = 8;

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

// Throws unless link index `link` fits the label image's 16 bits (as 1 + link, 0 meaning none).
void CheckLabelFits(int link) {
  if (link >= 0xFFFF) {
    throw Error("the label image holds 65534 links; link index " + std::to_string(link) + " does not fit");
  }
}

}  // namespace

struct SceneRenderer::Impl {
  Impl(int samples, const BackendChoice& backend)
      : samples(samples),
        context(CreateGlContext(backend.backend, backend.asked_by)),
        lit("lit.vert", "lit.frag") {
    glGenBuffers(1, &instance_buffer);
    glGenBuffers(2, cull_buffers);
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    can_cull = major > 4 || (major == 4 && minor >= 3);   // glMultiDrawElementsIndirect's version
    cull_small_triangles = can_cull;
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
    glDeleteBuffers(2, cull_buffers);
  }

  // Draws the instances of `batch` with the lit program, textured when its items are, and with
  // `labels` writing each instance's label and depth too (Framebuffer::StartLabels).
  void DrawBatch(const MeshBatch& batch, bool labels) {
    const bool textured = batch.key.texture_units > 0;
    const ShaderProgram& program =
        labels ? (textured ? lit_textured_labels.Get() : lit_labels.Get()) : (textured ? lit_textured.Get() : lit);
    program.Use();
    if (labels) program.Set("clip_to_view_depth", clip_to_view_depth);
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
    if (cull_small_triangles && cull->Cull(*batch.key.mesh, batch.mesh->centre(), batch.mesh->radius(),
                                           batch.key.mirrored, batch.instances, cull_indices, cull_commands)) {
      if (cull_commands.empty()) return;
      glBindBuffer(GL_ARRAY_BUFFER, cull_buffers[0]);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cull_indices.size() * sizeof(std::uint32_t)),
                   cull_indices.data(), GL_STREAM_DRAW);
      glBindBuffer(GL_ARRAY_BUFFER, cull_buffers[1]);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cull_commands.size() * sizeof(InstanceTriangles)),
                   cull_commands.data(), GL_STREAM_DRAW);
      batch.mesh->DrawInstanceRanges(instance_buffer, cull_buffers[0], cull_buffers[1],
                                     static_cast<int>(cull_commands.size()));
      return;
    }
    batch.mesh->DrawInstances(instance_buffer, static_cast<int>(batch.instances.size()));
  }

  // Draws the batches of `batches` in order (with `labels` as DrawBatch's) and empties it.
  void DrawBatches(MeshBatches& batches, bool labels = false) {
    for (const MeshBatch& batch : batches.batches()) DrawBatch(batch, labels);
    batches.Clear();
  }

  // The colour image: opaque geometry first, then transparent geometry, lines and text blended
  // back to front, as Ogre orders RViz's scene. With `labels`, the opaque meshes write their
  // labels and depths into the framebuffer too (see OneDrawLabels).
  image::Image DrawColour(const scene::Scene& scene, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P,
                          int width, int height, bool labels) {
    ClearColourFramebuffer(scene.background, width, height, labels);
    const Eigen::Vector3d eye = V.inverse().topRightCorner<3, 1>();
    if (labels) clip_to_view_depth = -Eigen::Vector4f(P.inverse().row(2).cast<float>());
    DrawBlended(DrawOpaque(scene, V, P, eye, labels), V, P, eye);
    return framebuffer->ReadPixels();
  }

  // Whether the colour pass draws the label and depth images too (one vertex pass instead of two).
  // It can when every draw item is an opaque link's (then the nearest item at a sample is the same
  // in both images: nothing but links writes depth among the items, and lines, text and blended
  // geometry write none) and GL multisamples integer images as the colour image is. It pays when
  // the items have many triangles for the image's size: a label pass costs llvmpipe ~57 ns a
  // triangle (126,598 triangles of Franka's Panda: 7.2 ms) besides its pixels, the label
  // attachment ~2.2 ms a 640x480 frame (multisampled clear, writes and resolve), so from about a
  // triangle per 8 pixels (docs/benchmarks.md, "Dataset samples").
  bool OneDrawLabels(const scene::Scene& scene, int width, int height) {
    if (!max_integer_samples) {
      int most = 0;
      glGetIntegerv(GL_MAX_INTEGER_SAMPLES, &most);
      max_integer_samples = most;
    }
    if (samples > *max_integer_samples) return false;
    long long triangles = 0;
    for (const auto& item : scene.items) {
      if (item.link < 0 || item.rgba.w() < kOpaqueAlpha) return false;
      triangles += meshes.Get(item.mesh).triangles();
    }
    return triangles * kPixelsPerTriangleForOneDraw >= static_cast<long long>(width) * height;
  }

  // Binds the colour framebuffer (made anew for another size, or with a label attachment when
  // `labels` first asks for one) cleared to `background`, depth-tested and back faces culled.
  void ClearColourFramebuffer(const Eigen::Vector3f& background, int width, int height, bool labels) {
    if (!framebuffer || framebuffer->width() != width || framebuffer->height() != height ||
        (labels && !framebuffer->labels())) {
      framebuffer.reset();
      framebuffer = std::make_unique<Framebuffer>(width, height, samples, labels);
      cull.reset();
    }
    framebuffer->Bind();
    if (!cull) {
      GLint sample_count = 0;
      glGetIntegerv(GL_SAMPLES, &sample_count);
      std::vector<Eigen::Vector2f> positions(std::max(sample_count, 1), Eigen::Vector2f(0.5f, 0.5f));
      for (GLint s = 0; s < sample_count; ++s) glGetMultisamplefv(GL_SAMPLE_POSITION, s, positions[s].data());
      cull.emplace(width, height, std::move(positions));
    }
    glClearColor(background.x(), background.y(), background.z(), 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
  }

  // Draws the opaque meshes (with `labels`, their labels and depths too), point sets and triangles,
  // writing depth; returns the rest (transparent ones, every line set and label) with their squared
  // distances from `eye`, back to front.
  std::vector<Transparent> DrawOpaque(const scene::Scene& scene, const Eigen::Matrix4d& V,
                                      const Eigen::Matrix4d& P, const Eigen::Vector3d& eye, bool labels) {
    const Eigen::Matrix4d PV = P * V;
    glDisable(GL_BLEND);
    std::vector<Transparent> transparent;
    for (const auto& item : scene.items) {
      if (labels) CheckLabelFits(item.link);
      if (item.rgba.w() >= kOpaqueAlpha) {
        batches.Add(item, meshes.Get(item.mesh), kMaxTextureUnits, V, PV, MeshBatches::Join::kAny);
      } else {
        transparent.push_back({(item.X_FG.translation() - eye).squaredNorm(), &item});
      }
    }
    if (labels) framebuffer->StartLabels();
    DrawBatches(batches, labels);
    if (labels) framebuffer->StopLabels();
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
        streamed.AddTriangles(triangles, PV);
      } else {
        transparent.push_back({(Centre(triangles.positions) - eye).squaredNorm(), &triangles});
      }
    }
    streamed.Flush();
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
        streamed.Flush();
        batches.Add(**item, meshes.Get((*item)->mesh), kMaxTextureUnits, V, PV, MeshBatches::Join::kLast);
        continue;
      }
      DrawBatches(batches);
      if (const auto* lines = std::get_if<const scene::LineSet*>(&t.what)) {
        streamed.AddLines(**lines, PV, eye);
      } else if (const auto* triangles = std::get_if<const scene::FlatTriangles*>(&t.what)) {
        streamed.AddTriangles(**triangles, PV);
      } else if (const auto* points = std::get_if<const scene::PointSet*>(&t.what)) {
        streamed.Flush();
        point_sets().Draw(**points, V, P);
      } else if (const scene::TextLabel& label = *std::get<const scene::TextLabel*>(t.what); !label.quads.empty()) {
        streamed.AddLabel(label, textures.Get(label.texture), V, P);
      }
    }
    DrawBatches(batches);
    streamed.Flush();
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
      CheckLabelFits(item.link);
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
  std::optional<int> max_integer_samples;      // GL's, asked when first needed
  std::unique_ptr<GlContext> context;
  ShaderProgram lit;                           // untextured surfaces
  LazyShaderProgram lit_textured{"lit.vert", "lit.frag", "TEXTURED"};   // and textured ones
  // the same writing labels and depths too, and what turns a clip-space position into its depth
  LazyShaderProgram lit_labels{"lit.vert", "lit.frag", "LABELS"};
  LazyShaderProgram lit_textured_labels{"lit.vert", "lit.frag", "TEXTURED LABELS"};
  Eigen::Vector4f clip_to_view_depth = Eigen::Vector4f::Zero();
  StreamedDrawing streamed;                    // lines, flat triangles and text labels
  LazyShaderProgram label{"label.vert", "label.frag"};
  // the point programs, made for the first point set drawn
  std::optional<PointSetDrawing> point_sets_made;
  PointSetDrawing& point_sets() {
    if (!point_sets_made) point_sets_made.emplace();
    return *point_sets_made;
  }
  unsigned instance_buffer = 0;                    // per-draw MeshInstances
  // the small triangles' culling: whether on, for the colour framebuffer's size and samples, and
  // what a batch draws (indices, one range per instance) with its buffers
  bool can_cull = false, cull_small_triangles = false;
  std::optional<CoverageCull> cull;
  std::vector<std::uint32_t> cull_indices;
  std::vector<InstanceTriangles> cull_commands;
  unsigned cull_buffers[2] = {0, 0};
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

void SceneRenderer::CullSmallTriangles(bool on) {
  impl_->cull_small_triangles = on && impl_->can_cull;
}

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
  const bool one_draw = outputs.colour && (outputs.depth || outputs.labels) && r.OneDrawLabels(scene, width, height);
  if (outputs.colour) frame.colour = r.DrawColour(scene, V, P, width, height, one_draw);
  if (one_draw) {
    image::DepthImage depth;
    image::LabelImage labels = r.framebuffer->ReadLabels(outputs.depth ? &depth : nullptr);
    if (outputs.depth) frame.depth = std::move(depth);
    if (outputs.labels) frame.labels = std::move(labels);
  } else if (outputs.depth || outputs.labels) {
    image::LabelImage labels = r.DrawLabels(scene, V, P, width, height);
    if (outputs.depth) frame.depth = r.label_framebuffer->ReadDepths(labels);
    if (outputs.labels) frame.labels = std::move(labels);
  }
  return frame;
}

}  // namespace urdfsnap::gl
