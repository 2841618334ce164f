/* The floor under `urdfsnap render`'s start-up on llvmpipe, for bench/startup: the least a process
 * that draws with OSMesa must pay in time and peak memory, measured at three depths:
 *   load      libOSMesa (and through it libLLVM) loaded and relocated, nothing called
 *   context   an OpenGL 3.3 core context made current (as urdfsnap's OSMesa backend makes it)
 *   triangle  one triangle drawn into a 640x480 framebuffer with SAMPLES samples (4 as RViz asks,
 *             0 for none), resolved and read back as RGB: llvmpipe JIT-compiles its shaders and
 *             set-up code, which is what pulls most of libLLVM's code into memory
 * usage: osmesa_floor load|context|triangle [SAMPLES]; prints the centre pixel for `triangle`. */
#include <stdlib.h>
#include <string.h>

#include "../osmesa/osmesa_gl.h"

static int DrawTriangle(int samples) {
  GL_FUNCTION(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  const GLuint resolved = Framebuffer(0, 0);
  const GLuint drawn = Framebuffer(samples, 1);
  UseFlatProgram();
  const float triangle[] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0, 0.5f, 0};
  BindPositions(triangle, sizeof triangle);
  glBindFramebuffer(GL_FRAMEBUFFER, drawn);
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  static unsigned char rgb[kWidth * kHeight * 3];
  ResolveAndRead(drawn, resolved, rgb);
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
  OSMesaContext context = MakeCoreContext("osmesa_floor");
  if (!context) return 1;
  const int status = strcmp(depth, "triangle") == 0 ? DrawTriangle(argc > 2 ? atoi(argv[2]) : 4) : 0;
  OSMesaDestroyContext(context);
  return status;
}
