// Draws Scenes into images with OpenGL, the way RViz's Ogre pipeline does: one head-light,
// per-vertex diffuse lighting, opaque geometry first, then transparent geometry and lines
// blended back to front, 4x multisampling. One Renderer owns one GL context; reuse it for many
// frames (meshes are uploaded once and kept).
#pragma once

#include <memory>

#include "image/image.h"
#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::gl {

class Renderer {
 public:
  // samples: multisampling per pixel, 4 as RViz requests (render_system.cpp L272-275); 0 = off.
  // Throws urdfsnap::Error when no GL context can be made.
  explicit Renderer(int samples = 4);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders `scene` seen through `view` into a width x height RGB image.
  image::Image Render(const scene::Scene& scene, const scene::OrbitView& view, int width, int height);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace urdfsnap::gl
