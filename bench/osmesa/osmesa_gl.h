/* What the plain-OSMesa floor programs share (bench/startup/osmesa_floor.c: a process's start-up;
 * bench/markers/triangle_floor.c: a frame of small triangles): an OpenGL 3.3 core context as
 * urdfsnap's OSMesa backend makes it, 640x480 framebuffers with some samples, a flat-colour
 * program, a buffer of triangles, and a frame resolved and read back as RGB. Header-only, so that
 * each program stays one `cc` command; no urdfsnap code in it. */
#pragma once

#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glcorearb.h>
#include <stddef.h>
#include <stdio.h>

enum { kWidth = 640, kHeight = 480 };

#define GL_FUNCTION(type, name) type name = (type)(void (*)(void))OSMesaGetProcAddress(#name)

/* An OpenGL 3.3 core context made current, or NULL with a line on stderr naming `program`. */
static inline OSMesaContext MakeCoreContext(const char* program) {
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, NULL);
  static unsigned char placeholder[4];
  if (!context || !OSMesaMakeCurrent(context, placeholder, GL_UNSIGNED_BYTE, 1, 1)) {
    fprintf(stderr, "%s: no OpenGL 3.3 core context\n", program);
    if (context) OSMesaDestroyContext(context);
    return NULL;
  }
  return context;
}

static inline GLuint Shader(GLenum kind, const char* source) {
  GL_FUNCTION(PFNGLCREATESHADERPROC, glCreateShader);
  GL_FUNCTION(PFNGLSHADERSOURCEPROC, glShaderSource);
  GL_FUNCTION(PFNGLCOMPILESHADERPROC, glCompileShader);
  GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, NULL);
  glCompileShader(shader);
  return shader;
}

/* The program drawing positions (attribute 0, clip space) in one colour, in use. */
static inline void UseFlatProgram(void) {
  GL_FUNCTION(PFNGLCREATEPROGRAMPROC, glCreateProgram);
  GL_FUNCTION(PFNGLATTACHSHADERPROC, glAttachShader);
  GL_FUNCTION(PFNGLLINKPROGRAMPROC, glLinkProgram);
  GL_FUNCTION(PFNGLUSEPROGRAMPROC, glUseProgram);
  const GLuint program = glCreateProgram();
  glAttachShader(program, Shader(GL_VERTEX_SHADER,
                                 "#version 330 core\nlayout(location = 0) in vec3 p;\n"
                                 "void main() { gl_Position = vec4(p, 1); }\n"));
  glAttachShader(program, Shader(GL_FRAGMENT_SHADER,
                                 "#version 330 core\nout vec4 colour;\n"
                                 "void main() { colour = vec4(1, 0.5, 0, 1); }\n"));
  glLinkProgram(program);
  glUseProgram(program);
}

/* `bytes` of x, y, z floats in a buffer bound as attribute 0 of a bound vertex array. */
static inline void BindPositions(const float* xyz, size_t bytes) {
  GL_FUNCTION(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays);
  GL_FUNCTION(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray);
  GL_FUNCTION(PFNGLGENBUFFERSPROC, glGenBuffers);
  GL_FUNCTION(PFNGLBINDBUFFERPROC, glBindBuffer);
  GL_FUNCTION(PFNGLBUFFERDATAPROC, glBufferData);
  GL_FUNCTION(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer);
  GL_FUNCTION(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray);
  GLuint array, buffer;
  glGenVertexArrays(1, &array);
  glBindVertexArray(array);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)bytes, xyz, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, NULL);
  glEnableVertexAttribArray(0);
}

/* A framebuffer of colour (and depth, when `depth`) renderbuffers with `samples` samples. */
static inline GLuint Framebuffer(int samples, int depth) {
  GL_FUNCTION(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers);
  GL_FUNCTION(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  GL_FUNCTION(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers);
  GL_FUNCTION(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer);
  GL_FUNCTION(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample);
  GL_FUNCTION(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer);
  GLuint framebuffer, buffers[2];
  glGenFramebuffers(1, &framebuffer);
  glGenRenderbuffers(2, buffers);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, kWidth, kHeight);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[0]);
  if (depth) {
    glBindRenderbuffer(GL_RENDERBUFFER, buffers[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, kWidth, kHeight);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, buffers[1]);
  }
  return framebuffer;
}

/* Resolves framebuffer `drawn` into `resolved` and reads it back into `rgb` (kWidth x kHeight x 3). */
static inline void ResolveAndRead(GLuint drawn, GLuint resolved, unsigned char* rgb) {
  GL_FUNCTION(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  GL_FUNCTION(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, drawn);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved);
  glBlitFramebuffer(0, 0, kWidth, kHeight, 0, 0, kWidth, kHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGB, GL_UNSIGNED_BYTE, rgb);
}
