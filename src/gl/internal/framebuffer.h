// The off-screen render targets: a multisampled colour+depth framebuffer resolved into a
// single-sample one and read back as a top-row-first RGB image, optionally with a second,
// unsigned-integer attachment holding each sample's link label and depth, read back one sample
// per pixel (the one-draw path of scene_renderer.cpp); and a single-sample one for the link-label
// and depth images drawn in a pass of their own. All are rasterised in a window's row order, as
// RViz's window is. Internal; needs a current context.
#pragma once

#include "image/image.h"

namespace urdfsnap::gl {

class Framebuffer {
 public:
  // samples = 0 renders without multisampling; `labels` adds the label-and-depth attachment (GL
  // must allow `samples` for integer formats, GL_MAX_INTEGER_SAMPLES). Throws urdfsnap::Error if
  // GL refuses the size.
  Framebuffer(int width, int height, int samples, bool labels);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  bool labels() const { return label_fbo_ != 0; }

  // Binds the framebuffer to draw into, colour only, and sets the viewport to its size.
  void Bind() const;
  // With labels(), after Bind: clears every sample's label and depth to "nothing" and draws them
  // too (fragment output 1: label, depth's float bits) until StopLabels.
  void StartLabels() const;
  void StopLabels() const;
  // Resolves the samples and reads the pixels back, top row first.
  image::Image ReadPixels() const;
  // With labels(): the labels (0 where nothing was drawn) and, when `depth`, the depths (NaN where
  // the label is 0) of one sample per pixel, the multisample pattern's first (where GL resolves
  // an integer image by taking one sample), top row first.
  image::LabelImage ReadLabels(image::DepthImage* depth) const;

 private:
  int width_, height_, samples_;
  unsigned draw_fbo_ = 0, resolve_fbo_ = 0, label_fbo_ = 0;
  // draw colour, draw depth, resolved colour, draw labels and depths, resolved labels and depths
  unsigned renderbuffers_[5] = {0, 0, 0, 0, 0};
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
