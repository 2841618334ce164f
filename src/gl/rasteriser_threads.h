// How many threads Mesa's llvmpipe rasterises on when a command keeps other threads busy beside
// the render thread (animate's encoder): llvmpipe takes one thread per core by default, and on a
// small machine those threads and the encoder then take turns on the same cores.
#pragma once

#include <string>

namespace urdfsnap::gl {

// Leaves `busy_threads` cores to the caller's other threads: llvmpipe gets the cores that remain
// beyond the render thread's own (LP_NUM_THREADS), none on 2 cores with one encoder, where it
// then rasterises on the render thread itself. A GPU is not affected, nor an LP_NUM_THREADS the
// user set. It sets an environment variable, so call it before StartLoadingGl, while the process
// has one thread. Returns what --verbose says about it ("" when the user's setting stands), e.g.
// "LP_NUM_THREADS=0: llvmpipe rasterises on the render thread, 1 core left to encoding".
std::string LeaveCoresToOtherThreads(int busy_threads);

}  // namespace urdfsnap::gl
