// Framebuffer objects for multisampled off-screen rendering, the label/depth target, and read-back.
#include "gl/internal/framebuffer.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.h"
#include "gl/internal/gl_api.h"

namespace urdfsnap::gl {

namespace {

void Check(GLuint fbo, int width, int height, int samples) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("OpenGL cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels with " + std::to_string(samples) + " samples");
  }
}

// Lays the bound framebuffer's rows out top row first, as Mesa lays out a window's: RViz draws
// into its window, and Mesa's state tracker rasterises window-system framebuffers with y = 0 at
// the top ("Y_0_TOP", st_fb_orientation in src/mesa/state_tracker/st_context.h) but framebuffer
// objects with y = 0 at the bottom. llvmpipe's four sample positions (lp_sample_pos_4x in
// lp_rast.c) are fixed in the buffer's own rows, so in an ordinary framebuffer object they lie
// mirrored top to bottom against RViz's window, and every anti-aliased edge covers different
// samples: on the Kinova arm 1-2% of the robot's edge pixels crossed the reference images'
// robot-mask threshold the other way (iou 0.981-0.988), and grid lines differed on ~2,100
// pixels. GL_MESA_framebuffer_flip_y gives an object the window's orientation; everything GL
// reports (viewport, read-back, blits) stays bottom-up, so nothing else changes. Drivers without
// the extension keep their own layout: the same image but for edge pixels.
void UseWindowRowOrder() {
  constexpr GLenum kFramebufferFlipYMesa = 0x8BBB;   // GL_FRAMEBUFFER_FLIP_Y_MESA
  glFramebufferParameteri(GL_FRAMEBUFFER, kFramebufferFlipYMesa, GL_TRUE);
  while (glGetError() != GL_NO_ERROR) {
    // GL_INVALID_ENUM without the extension: the layout stays the driver's
  }
}

// Reads `components` values of `type` per pixel from the bound read framebuffer's current buffer
// and returns them with the top row first.
template <typename T>
std::vector<T> ReadRows(int width, int height, int components, GLenum format, GLenum type) {
  std::vector<T> values(static_cast<size_t>(width) * height * components);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, format, type, values.data());
  // GL's first row is the bottom one; images start at the top
  const size_t stride = static_cast<size_t>(width) * components;
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(values.begin() + y * stride, values.begin() + (y + 1) * stride,
                     values.begin() + (height - 1 - y) * stride);
  }
  return values;
}

}  // namespace

Framebuffer::Framebuffer(int width, int height, int samples, bool labels)
    : width_(width), height_(height), samples_(samples) {
  glGenRenderbuffers(labels ? 5 : 3, renderbuffers_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  // 24-bit depth, like the Ogre GL render system RViz uses
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);

  glGenFramebuffers(1, &draw_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
  if (labels) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[3]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RG32UI, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, renderbuffers_[3]);
  }
  UseWindowRowOrder();
  Check(draw_fbo_, width, height, samples);

  glGenFramebuffers(1, &resolve_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[2]);
  Check(resolve_fbo_, width, height, 0);

  if (labels) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[4]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RG32UI, width, height);
    glGenFramebuffers(1, &label_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, label_fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[4]);
    Check(label_fbo_, width, height, 0);
  }
}

Framebuffer::~Framebuffer() {
  glDeleteFramebuffers(1, &draw_fbo_);
  glDeleteFramebuffers(1, &resolve_fbo_);
  if (label_fbo_ != 0) glDeleteFramebuffers(1, &label_fbo_);
  glDeleteRenderbuffers(label_fbo_ != 0 ? 5 : 3, renderbuffers_);
}

void Framebuffer::Bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glViewport(0, 0, width_, height_);
  if (labels()) StopLabels();
}

void Framebuffer::StartLabels() const {
  const GLenum outputs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, outputs);
  const GLuint nothing[4] = {0, 0, 0, 0};
  glClearBufferuiv(GL_COLOR, 1, nothing);
}

void Framebuffer::StopLabels() const {
  const GLenum outputs[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glDrawBuffers(2, outputs);
}

image::Image Framebuffer::ReadPixels() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  return {width_, height_, ReadRows<std::uint8_t>(width_, height_, 3, GL_RGB, GL_UNSIGNED_BYTE)};
}

image::LabelImage Framebuffer::ReadLabels(image::DepthImage* depth) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, label_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, label_fbo_);
  const std::vector<std::uint32_t> pairs = ReadRows<std::uint32_t>(width_, height_, 2, GL_RG_INTEGER, GL_UNSIGNED_INT);
  const size_t pixels = pairs.size() / 2;
  image::LabelImage labels{width_, height_, std::vector<std::uint16_t>(pixels)};
  if (depth) *depth = {width_, height_, std::vector<float>(pixels)};
  for (size_t i = 0; i < pixels; ++i) {
    labels.labels[i] = static_cast<std::uint16_t>(pairs[2 * i]);
    if (depth) depth->metres[i] = pairs[2 * i] == 0 ? std::nanf("") : std::bit_cast<float>(pairs[2 * i + 1]);
  }
  return labels;
}

LabelFramebuffer::LabelFramebuffer(int width, int height) : width_(width), height_(height) {
  glGenRenderbuffers(3, renderbuffers_);
  const GLenum formats[3] = {GL_R16UI, GL_R32F, GL_DEPTH_COMPONENT32F};
  for (int k = 0; k < 3; ++k) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[k]);
    glRenderbufferStorage(GL_RENDERBUFFER, formats[k], width, height);
  }
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, renderbuffers_[1]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[2]);
  const GLenum outputs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, outputs);
  UseWindowRowOrder();   // so labels and depths cover the colour image's pixels
  Check(fbo_, width, height, 0);
}

LabelFramebuffer::~LabelFramebuffer() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(3, renderbuffers_);
}

void LabelFramebuffer::BindAndClear() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
  const GLuint no_label[4] = {0, 0, 0, 0};
  const GLfloat no_depth[4] = {0, 0, 0, 0};
  const GLfloat far = 1;
  glClearBufferuiv(GL_COLOR, 0, no_label);
  glClearBufferfv(GL_COLOR, 1, no_depth);
  glClearBufferfv(GL_DEPTH, 0, &far);
}

image::LabelImage LabelFramebuffer::ReadLabels() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  return {width_, height_, ReadRows<std::uint16_t>(width_, height_, 1, GL_RED_INTEGER, GL_UNSIGNED_SHORT)};
}

image::DepthImage LabelFramebuffer::ReadDepths(const image::LabelImage& labels) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  image::DepthImage depth{width_, height_, ReadRows<float>(width_, height_, 1, GL_RED, GL_FLOAT)};
  for (size_t i = 0; i < depth.metres.size(); ++i) {
    if (labels.labels[i] == 0) depth.metres[i] = std::nanf("");
  }
  return depth;
}

}  // namespace urdfsnap::gl
