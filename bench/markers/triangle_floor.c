/* The floor under a marker frame on llvmpipe, for bench/markers/triangle_floor.sh: what any program
 * drawing through OSMesa pays for TRIANGLES small triangles a frame, whatever draws them. A
 * 640x480 frame with SAMPLES samples (4 as RViz asks) is cleared, the triangles (each about EDGE
 * pixels on a side, facing the camera, at random places and depths in the middle of the image) are
 * drawn in one glDrawArrays with a flat-colour shader and the depth test, and the frame is resolved
 * and read back as RGB, FRAMES times after a warm-up. Prints the median wall time and the mean CPU
 * time of all threads per frame, in ms. The shading is the least there is: a marker's lit shader,
 * its vertex attributes and its draw calls only add to it.
 * usage: triangle_floor TRIANGLES [EDGE [SAMPLES [FRAMES]]]   (defaults -, 3, 4, 30) */
#include <stdlib.h>
#include <time.h>

#include "../osmesa/osmesa_gl.h"

static double Seconds(clockid_t clock) {
  struct timespec t;
  clock_gettime(clock, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int Ascending(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

/* `count` triangles of about `edge` pixels in clip space, counter-clockwise, seeded. */
static float* Triangles(int count, float edge) {
  float* xyz = malloc(sizeof(float) * 9 * (size_t)(count > 0 ? count : 1));
  if (!xyz) return NULL;
  srand(7);
  const float sx = 2.f * edge / kWidth, sy = 2.f * edge / kHeight;
  for (int i = 0; i < count; ++i) {
    const float x = 1.2f * ((float)rand() / RAND_MAX - 0.5f), y = 1.2f * ((float)rand() / RAND_MAX - 0.5f);
    const float z = (float)rand() / RAND_MAX - 0.5f;
    const float corners[9] = {x, y, z, x + sx, y, z, x + 0.5f * sx, y + sy, z};
    for (int k = 0; k < 9; ++k) xyz[9 * i + k] = corners[k];
  }
  return xyz;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: triangle_floor TRIANGLES [EDGE [SAMPLES [FRAMES]]]\n");
    return 2;
  }
  const int count = atoi(argv[1]);
  const float edge = argc > 2 ? (float)atof(argv[2]) : 3.f;
  const int samples = argc > 3 ? atoi(argv[3]) : 4;
  const int frames = argc > 4 ? atoi(argv[4]) : 30;
  OSMesaContext context = MakeCoreContext("triangle_floor");
  if (!context) return 1;
  GL_FUNCTION(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
  const GLuint resolved = Framebuffer(0, 0);
  const GLuint drawn = Framebuffer(samples, 1);
  UseFlatProgram();
  float* xyz = Triangles(count, edge);
  double* wall = malloc(sizeof(double) * (size_t)(frames > 0 ? frames : 1));
  static unsigned char rgb[kWidth * kHeight * 3];
  if (!xyz || !wall || frames < 1) return 1;
  BindPositions(xyz, sizeof(float) * 9 * (size_t)count);
  glViewport(0, 0, kWidth, kHeight);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  double cpu = 0;
  for (int frame = -1; frame < frames; ++frame) {   /* frame -1: the warm-up */
    const double wall_start = Seconds(CLOCK_MONOTONIC), cpu_start = Seconds(CLOCK_PROCESS_CPUTIME_ID);
    glBindFramebuffer(GL_FRAMEBUFFER, drawn);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 3 * count);
    ResolveAndRead(drawn, resolved, rgb);
    if (frame < 0) continue;
    wall[frame] = Seconds(CLOCK_MONOTONIC) - wall_start;
    cpu += Seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu_start;
  }
  qsort(wall, (size_t)frames, sizeof(double), Ascending);
  printf("%d triangles of %.1f px, %d samples: %.2f ms wall (median), %.2f ms CPU per frame\n", count, edge,
         samples, 1000 * wall[frames / 2], 1000 * cpu / frames);
  free(xyz);
  free(wall);
  OSMesaDestroyContext(context);
  return glGetError() == GL_NO_ERROR ? 0 : 1;
}
