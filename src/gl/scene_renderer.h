// Draws Scenes into images with OpenGL, the way RViz's Ogre pipeline does: one head-light,
// per-vertex diffuse lighting, opaque geometry first, then transparent geometry and lines
// blended back to front, 4x multisampling; and, from the same scene and view, the depth and
// link-label images of the robot's geometry. One SceneRenderer owns one GL context; reuse it for many
// frames (meshes and textures are uploaded once and kept while the scene objects live).
#pragma once

#include <memory>
#include <string>

#include "gl/backend.h"
#include "image/image.h"
#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::gl {

class SceneRenderer {
 public:
  // samples: multisampling per pixel, 4 as RViz requests (render_system.cpp L272-275); 0 = off.
  // backend: the GL backend asked for ({} when none is: URDFSNAP_GL_BACKEND, else auto; see
  // CreateGlContext), and whom to tell which one the context uses. Throws urdfsnap::Error when no
  // GL context can be made.
  explicit SceneRenderer(int samples = 4, const BackendChoice& backend = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Renders `scene` seen through `view` into width x height images: the colour image as RViz
  // shows it, and the depth and label images of the draw items with a link (robot geometry; never
  // the grid, TF markers, names or point sets), as `outputs` asks. Throws urdfsnap::Error when GL
  // cannot render the size, or a draw item's link index does not fit a 16-bit label.
  image::Frame Render(const scene::Scene& scene, const scene::OrbitView& view, int width, int height,
                      const image::FrameOutputs& outputs = {});

  // As above, through any camera: `view` takes the scene's frame to GL's eye frame (looking down
  // −Z, +Y up) and `projection` the eye frame to clip space (a calibrated camera's, see
  // camera::GlProjection). The depth image holds −z of the eye frame.
  image::Frame Render(const scene::Scene& scene, const Eigen::Matrix4d& view, const Eigen::Matrix4d& projection,
                      int width, int height, const image::FrameOutputs& outputs = {});

  // Leaves the context current on no thread (Render makes it current again), so that the next
  // Render may come from another thread: EGL lets a context be current on one thread only. For
  // callers that hand a SceneRenderer from thread to thread (the Python module); one thread at a time.
  void ReleaseContext();

  // Whether the lit shapes' triangles that cannot cover a sample are dropped before GL sees them
  // (gl/internal/coverage_cull.h; on unless GL lacks glMultiDrawElementsIndirect): the same
  // pixels either way, so off is for tests and measurements.
  void CullSmallTriangles(bool on);

  // The backend of the context (kOsMesa or kEgl), its one-line description and the line saying
  // which backend was taken and why (GlContext's).
  Backend backend() const;
  const std::string& description() const;
  std::string Summary() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace urdfsnap::gl
