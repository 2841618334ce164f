// The off-screen render target: a multisampled colour+depth framebuffer resolved into a
// single-sample one and read back as a top-row-first RGB image. Internal; needs a current context.
#pragma once

#include "image/image.h"

namespace urdfsnap::gl {

class Framebuffer {
 public:
  // samples = 0 renders without multisampling. Throws urdfsnap::Error if GL refuses the size.
  Framebuffer(int width, int height, int samples);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

  // Binds the framebuffer to draw into and sets the viewport to its size.
  void Bind() const;
  // Resolves the samples and reads the pixels back, top row first.
  image::Image ReadPixels() const;

 private:
  int width_, height_, samples_;
  unsigned draw_fbo_ = 0, resolve_fbo_ = 0;
  unsigned renderbuffers_[3] = {0, 0, 0};   // draw colour, draw depth, resolved colour
};

}  // namespace urdfsnap::gl
