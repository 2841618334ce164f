// LeaveCoresToOtherThreads: LP_NUM_THREADS from the cores the process may run on and the scene.
//
// Measured on 2 cores (bench/animate/animate_bench.sh, mrm of ~2,000 triangles, 1,000 frames at
// 640x480): with llvmpipe's default of 2 rasteriser threads beside the encoder, PNG 280, WebP 265
// and MP4 315 frames/s; rasterising on the render thread, 325, 295 and 330. A mesh robot is the
// other way round: for the Panda turntable (135,000 triangles, 4x MSAA, PNG) the rasteriser spends
// ~27 of the ~40 ms of CPU per frame (perf record by thread), which on the render thread alone
// caps it at ~25 frames/s, while the PNG encoder needs ~2 ms a frame. With a rasteriser thread
// per core the render thread's own part is ~6 ms a frame. The output is the same either way
// (llvmpipe's tiles do not depend on the threads that draw them).
#include "gl/rasteriser_threads.h"

#include <stdlib.h>

#include <algorithm>

#include "common/usable_cores.h"

namespace urdfsnap::gl {

std::string LeaveCoresToOtherThreads(int busy_threads, std::size_t triangles) {
  if (getenv("LP_NUM_THREADS") != nullptr) return "";
  const bool raster_bound = triangles >= kRasterBoundTriangles;
  const int cores = UsableCores();
  const int threads = raster_bound ? cores : std::max(0, cores - 1 - busy_threads);
  const std::string value = std::to_string(threads);
  setenv("LP_NUM_THREADS", value.c_str(), 1);
  if (raster_bound) {
    return "LP_NUM_THREADS=" + value + ": llvmpipe rasterises on " + value + (threads == 1 ? " thread" : " threads") +
           ", one per core: drawing " + std::to_string(triangles) + " triangles outweighs encoding";
  }
  const std::string busy = std::to_string(busy_threads) + (busy_threads == 1 ? " core" : " cores");
  if (threads == 0) {
    return "LP_NUM_THREADS=0: llvmpipe rasterises on the render thread, " + busy + " left to encoding";
  }
  return "LP_NUM_THREADS=" + value + ": llvmpipe rasterises on " + value + " threads, " + busy +
         " left to encoding";
}

}  // namespace urdfsnap::gl
