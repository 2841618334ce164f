/* The floor under `urdfsnap render`'s start-up on llvmpipe, for bench/startup: the least a process
 * that draws with OSMesa must pay in time and peak memory, measured at three depths:
 *   load      libOSMesa (and through it libLLVM) loaded and relocated, nothing called
 *   context   an OpenGL 3.3 core context made current (as urdfsnap's OSMesa backend makes it)
 *   triangle  one triangle drawn into a 640x480 framebuffer with SAMPLES samples (4 as RViz asks,
 *             0 for none), resolved and read back as RGB: llvmpipe JIT-compiles its shaders and
 *             set-up code, which is what pulls most of libLLVM's code into memory
 * usage: osmesa_floor load|context|triangle [SAMPLES]; prints the centre pixel for `triangle`. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glcorearb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kWidth = 640, kHeight = 480 };

#define GL_FUNCTION(type, name) type name = (type)(void (*)(void))OSMesaGetProcAddress(#name)

static GLuint Shader(GLenum kind, const char* source) {
  GL_FUNCTION(PFNGLCREATESHADERPROC, glCreateShader);
  GL_FUNCTION(PFNGLSHADERSOURCEPROC, glShaderSource);
  GL_FUNCTION(PFNGLCOMPILESHADERPROC, glCompileShader);
  GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, NULL);
  glCompileShader(shader);
  return shader;
}

/* A framebuffer of colour (and depth, when `depth`) renderbuffers with `samples` samples. */
static GLuint Framebuffer(int samples, int depth) {
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

static int DrawTriangle(int samples) {
  GL_FUNCTION(PFNGLCREATEPROGRAMPROC, glCreateProgram);
  GL_FUNCTION(PFNGLATTACHSHADERPROC, glAttachShader);
  GL_FUNCTION(PFNGLLINKPROGRAMPROC, glLinkProgram);
  GL_FUNCTION(PFNGLUSEPROGRAMPROC, glUseProgram);
  GL_FUNCTION(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays);
  GL_FUNCTION(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray);
  GL_FUNCTION(PFNGLGENBUFFERSPROC, glGenBuffers);
  GL_FUNCTION(PFNGLBINDBUFFERPROC, glBindBuffer);
  GL_FUNCTION(PFNGLBUFFERDATAPROC, glBufferData);
  GL_FUNCTION(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer);
  GL_FUNCTION(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray);
  GL_FUNCTION(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  GL_FUNCTION(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer);
  const GLuint resolved = Framebuffer(0, 0);
  const GLuint drawn = Framebuffer(samples, 1);
  const GLuint program = glCreateProgram();
  glAttachShader(program, Shader(GL_VERTEX_SHADER,
                                 "#version 330 core\nlayout(location = 0) in vec3 p;\n"
                                 "void main() { gl_Position = vec4(p, 1); }\n"));
  glAttachShader(program, Shader(GL_FRAGMENT_SHADER,
                                 "#version 330 core\nout vec4 colour;\n"
                                 "void main() { colour = vec4(1, 0.5, 0, 1); }\n"));
  glLinkProgram(program);
  glUseProgram(program);
  const float triangle[] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0, 0.5f, 0};
  GLuint array, buffer;
  glGenVertexArrays(1, &array);
  glBindVertexArray(array);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof triangle, triangle, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, NULL);
  glEnableVertexAttribArray(0);
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, drawn);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved);
  glBlitFramebuffer(0, 0, kWidth, kHeight, 0, 0, kWidth, kHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved);
  static unsigned char rgb[kWidth * kHeight * 3];
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  const unsigned char* centre = rgb + ((kHeight / 2) * kWidth + kWidth / 2) * 3;
  printf("centre pixel %d %d %d\n", centre[0], centre[1], centre[2]);
  return glGetError() == GL_NO_ERROR ? 0 : 1;
}

int main(int argc, char** argv) {
  const char* depth = argc > 1 ? argv[1] : "";
  if (strcmp(depth, "load") == 0) return 0;
  if (strcmp(depth, "context") != 0 && strcmp(depth, "triangle") != 0) {
    fprintf(stderr, "usage: osmesa_floor load|context|triangle [SAMPLES]\n");
    return 2;
  }
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, NULL);
  static unsigned char placeholder[4];
  if (!context || !OSMesaMakeCurrent(context, placeholder, GL_UNSIGNED_BYTE, 1, 1)) {
    fprintf(stderr, "osmesa_floor: no OpenGL 3.3 core context\n");
    return 1;
  }
  const int status = strcmp(depth, "triangle") == 0 ? DrawTriangle(argc > 2 ? atoi(argv[2]) : 4) : 0;
  OSMesaDestroyContext(context);
  return status;
}
