// OpenGL drawing of a Scene: state setup, draw order and per-item uniforms.
#include "render/renderer.h"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "render/framebuffer.h"
#include "render/gl_api.h"
#include "render/gl_context.h"
#include "render/gpu_mesh.h"
#include "render/shader_program.h"

namespace urdfsnap::render {

namespace {

// Below this alpha Ogre (and so RViz) switches a material to blended, depth-write-off rendering
// (robot_link.cpp L383-430, grid.cpp L115-130).
constexpr float kOpaqueAlpha = 0.9998f;

struct Transparent {
  double depth;            // squared distance from the eye, for back-to-front order
  const DrawItem* item;    // exactly one of item and lines is set
  const LineSet* lines;
};

}  // namespace

struct Renderer::Impl {
  explicit Impl(int samples)
      : samples(samples),
        context(CreateOsMesaContext()),
        lit("lit.vert", "lit.frag"),
        line("line.vert", "line.frag") {
    glGenVertexArrays(1, &line_array);
    glGenBuffers(1, &line_buffer);
  }
  ~Impl() {
    glDeleteBuffers(1, &line_buffer);
    glDeleteVertexArrays(1, &line_array);
  }

  const GpuMesh& Upload(const std::shared_ptr<const geometry::TriangleMesh>& mesh) {
    auto it = meshes.find(mesh.get());
    if (it == meshes.end()) {
      it = meshes.try_emplace(mesh.get(), mesh, std::make_unique<GpuMesh>(*mesh)).first;
    }
    return *it->second.second;
  }

  void DrawItem(const render::DrawItem& item, const Eigen::Matrix4d& V, const Eigen::Matrix4d& PV) {
    const Eigen::Matrix4d M = item.X_FG.matrix();
    lit.Set("model_view_projection", Eigen::Matrix4f((PV * M).cast<float>()));
    const Eigen::Matrix3d MV = (V * M).topLeftCorner<3, 3>();
    lit.Set("normal_to_view", Eigen::Matrix3f(MV.inverse().transpose().cast<float>()));
    lit.Set("diffuse", item.rgba);
    // a mirroring scale turns the winding around; Ogre flips culling for such nodes, and so do we
    glFrontFace(M.topLeftCorner<3, 3>().determinant() < 0 ? GL_CW : GL_CCW);
    Upload(item.mesh).Draw();
  }

  void DrawLines(const LineSet& lines, const Eigen::Matrix4d& PV) {
    line.Use();
    line.Set("model_view_projection", Eigen::Matrix4f(PV.cast<float>()));
    line.Set("colour", lines.rgba);
    glBindVertexArray(line_array);
    glBindBuffer(GL_ARRAY_BUFFER, line_buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.points.size() * sizeof(Eigen::Vector3f)),
                 lines.points.data(), GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Eigen::Vector3f), nullptr);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.points.size()));
  }

  int samples;
  std::unique_ptr<GlContext> context;
  ShaderProgram lit;
  ShaderProgram line;
  unsigned line_array = 0, line_buffer = 0;
  std::unique_ptr<Framebuffer> framebuffer;
  // keyed by the mesh's address; the shared_ptr keeps that address from being reused
  std::unordered_map<const geometry::TriangleMesh*,
                     std::pair<std::shared_ptr<const geometry::TriangleMesh>, std::unique_ptr<GpuMesh>>>
      meshes;
};

Renderer::Renderer(int samples) : impl_(std::make_unique<Impl>(samples)) {}

Renderer::~Renderer() = default;

image::Image Renderer::Render(const Scene& scene, const OrbitView& view, int width, int height) {
  Impl& r = *impl_;
  r.context->MakeCurrent();
  if (!r.framebuffer || r.framebuffer->width() != width || r.framebuffer->height() != height) {
    r.framebuffer.reset();
    r.framebuffer = std::make_unique<Framebuffer>(width, height, r.samples);
  }
  r.framebuffer->Bind();

  const Eigen::Matrix4d V = ViewMatrix(view);
  const Eigen::Matrix4d PV = ProjectionMatrix(view, static_cast<double>(width) / height) * V;
  const Eigen::Vector3d eye = EyePosition(view);

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
      r.DrawItem(item, V, PV);
    } else {
      transparent.push_back({(item.X_FG.translation() - eye).squaredNorm(), &item, nullptr});
    }
  }
  for (const auto& lines : scene.lines) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : lines.points) centre += p.cast<double>();
    if (!lines.points.empty()) centre /= static_cast<double>(lines.points.size());
    transparent.push_back({(centre - eye).squaredNorm(), nullptr, &lines});
  }

  // then blended geometry back to front, depth-tested but not writing depth
  std::stable_sort(transparent.begin(), transparent.end(),
                   [](const Transparent& a, const Transparent& b) { return a.depth > b.depth; });
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  for (const auto& t : transparent) {
    if (t.item) {
      r.lit.Use();
      r.DrawItem(*t.item, V, PV);
    } else {
      r.DrawLines(*t.lines, PV);
    }
  }
  glDepthMask(GL_TRUE);
  return r.framebuffer->ReadPixels();
}

}  // namespace urdfsnap::render
