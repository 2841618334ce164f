/* MuJoCo's peer of `urdfsnap render` for bench/startup: mj_loadXML of a model (MJCF, or URDF as
 * MuJoCo reads it), one 640x480 frame drawn off-screen by MuJoCo's own renderer on an OSMesa
 * context (llvmpipe, as urdfsnap's), read back and written as a PNG (libpng). The whole process is
 * what the benchmark times; built there from Debian's libmujoco-dev when it is installed.
 * usage: mujoco_peer MODEL OUT.png */
#include <GL/osmesa.h>
#include <mujoco/mujoco.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>

enum { kWidth = 640, kHeight = 480 };

static int WritePng(const char* path, const unsigned char* rgb) {
  FILE* file = fopen(path, "wb");
  if (!file) return 0;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, file);
  png_set_IHDR(png, info, kWidth, kHeight, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  /* GL's first row is the bottom one */
  for (int y = kHeight - 1; y >= 0; --y) png_write_row(png, (png_const_bytep)(rgb + y * kWidth * 3));
  png_write_end(png, NULL);
  png_destroy_write_struct(&png, &info);
  return fclose(file) == 0;
}

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: mujoco_peer MODEL OUT.png\n");
    return 2;
  }
  char error[1000] = "";
  mjModel* model = mj_loadXML(argv[1], NULL, error, sizeof error);
  if (!model) {
    fprintf(stderr, "mujoco_peer: %s\n", error);
    return 2;
  }
  mjData* data = mj_makeData(model);
  mj_forward(model, data);

  /* MuJoCo's renderer wants a compatibility-profile context; it draws into its own
   * multisampled off-screen framebuffer (4 samples by default) */
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
  static unsigned char window[kWidth * kHeight * 4];
  if (!context || !OSMesaMakeCurrent(context, window, GL_UNSIGNED_BYTE, kWidth, kHeight)) {
    fprintf(stderr, "mujoco_peer: no OSMesa context\n");
    return 2;
  }
  mjvCamera camera;
  mjvOption option;
  mjvScene scene;
  mjrContext render;
  mjv_defaultCamera(&camera);
  /* the whole model from above at 45 degrees, as RViz's default view looks */
  camera.type = mjCAMERA_FREE;
  for (int i = 0; i < 3; ++i) camera.lookat[i] = model->stat.center[i];
  camera.distance = 3 * model->stat.extent;
  camera.azimuth = 45;
  camera.elevation = -35;
  mjv_defaultOption(&option);
  mjv_defaultScene(&scene);
  mjr_defaultContext(&render);
  mjv_makeScene(model, &scene, 2000);
  mjr_makeContext(model, &render, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_OFFSCREEN, &render);
  const mjrRect viewport = {0, 0, kWidth, kHeight};
  mjv_updateScene(model, data, &option, NULL, &camera, mjCAT_ALL, &scene);
  mjr_render(viewport, &scene, &render);
  unsigned char* rgb = malloc(kWidth * kHeight * 3);
  mjr_readPixels(rgb, NULL, viewport, &render);
  if (!WritePng(argv[2], rgb)) {
    fprintf(stderr, "mujoco_peer: cannot write %s\n", argv[2]);
    return 2;
  }
  free(rgb);
  mjr_freeContext(&render);
  mjv_freeScene(&scene);
  mj_deleteData(data);
  mj_deleteModel(model);
  OSMesaDestroyContext(context);
  return 0;
}
