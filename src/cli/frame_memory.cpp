// ReuseFreedFrameMemory: mallopt's mmap and trim thresholds.
#include "cli/frame_memory.h"

#include <malloc.h>

namespace urdfsnap::cli {

void ReuseFreedFrameMemory() {
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
}

}  // namespace urdfsnap::cli
