// Framebuffer objects for multisampled off-screen rendering and read-back.
#include "gl/framebuffer.h"

#include <algorithm>
#include <string>

#include "common/error.h"
#include "gl/gl_api.h"

namespace urdfsnap::gl {

namespace {

void Check(GLuint fbo, int width, int height, int samples) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("OpenGL cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels with " + std::to_string(samples) + " samples");
  }
}

}  // namespace

Framebuffer::Framebuffer(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples) {
  glGenRenderbuffers(3, renderbuffers_);
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
  Check(draw_fbo_, width, height, samples);

  glGenFramebuffers(1, &resolve_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[2]);
  Check(resolve_fbo_, width, height, 0);
}

Framebuffer::~Framebuffer() {
  glDeleteFramebuffers(1, &draw_fbo_);
  glDeleteFramebuffers(1, &resolve_fbo_);
  glDeleteRenderbuffers(3, renderbuffers_);
}

void Framebuffer::Bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glViewport(0, 0, width_, height_);
}

image::Image Framebuffer::ReadPixels() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  image::Image image;
  image.width = width_;
  image.height = height_;
  image.rgb.resize(static_cast<size_t>(width_) * height_ * 3);
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
  // GL's first row is the bottom one; images start at the top
  const size_t stride = static_cast<size_t>(width_) * 3;
  for (int y = 0; y < height_ / 2; ++y) {
    std::swap_ranges(image.rgb.begin() + y * stride, image.rgb.begin() + (y + 1) * stride,
                     image.rgb.begin() + (height_ - 1 - y) * stride);
  }
  return image;
}

}  // namespace urdfsnap::gl
