// The off-screen render targets: a multisampled colour+depth framebuffer resolved into a
// single-sample one and read back as a top-row-first RGB image; and a single-sample one for the
// link-label and depth images. Both are rasterised in a window's row order, as RViz's window is.
// Internal; needs a current context.
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

// One sample per pixel: a 16-bit unsigned label and a 32-bit float depth (metres) per pixel, with
// a depth buffer, so the nearest surface wins and values are exact (no multisample blend).
class LabelFramebuffer {
 public:
  // Throws urdfsnap::Error if GL refuses the size.
  LabelFramebuffer(int width, int height);
  ~LabelFramebuffer();
  LabelFramebuffer(const LabelFramebuffer&) = delete;
  LabelFramebuffer& operator=(const LabelFramebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  // Binds it to draw into (both outputs), sets the viewport and clears labels, depths and the
  // depth buffer to "nothing".
  void BindAndClear() const;
  // Reads the labels back, top row first (0 where nothing was drawn).
  image::LabelImage ReadLabels() const;
  // Reads the depths back, top row first; NaN where `labels` is 0.
  image::DepthImage ReadDepths(const image::LabelImage& labels) const;

 private:
  int width_, height_;
  unsigned fbo_ = 0;
  unsigned renderbuffers_[3] = {0, 0, 0};   // labels, depths, depth buffer
};

}  // namespace urdfsnap::gl
