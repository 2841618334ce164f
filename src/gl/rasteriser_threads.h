// How many threads Mesa's llvmpipe rasterises on when a command keeps other threads busy beside
// the render thread (animate's encoder): llvmpipe takes one thread per core by default, and on a
// small machine those threads and the encoder then take turns on the same cores. Which way is
// faster depends on the scene: light scenes rasterise in a moment and the encoder should have its
// core, mesh robots spend most of each frame rasterising and should have every core.
#pragma once

#include <cstddef>
#include <string>

namespace urdfsnap::gl {

// Scenes of at least this many triangles are rasterised on every core (see rasteriser_threads.cpp
// for the measurements behind it).
inline constexpr std::size_t kRasterBoundTriangles = 20'000;

// Leaves `busy_threads` cores to the caller's other threads when the scene has fewer than
// kRasterBoundTriangles `triangles`: llvmpipe gets the cores that remain beyond the render
// thread's own (LP_NUM_THREADS), none on 2 cores with one encoder, where it then rasterises on the
// render thread itself. A heavier scene gets a rasteriser thread per core. A GPU is not affected,
// nor an LP_NUM_THREADS the user set. It sets an environment variable, so call it before the
// first GL context is made, while no other thread runs (after StartLoadingGl's has ended).
// Returns what --verbose says about it ("" when the user's setting stands), e.g.
// "LP_NUM_THREADS=0: llvmpipe rasterises on the render thread, 1 core left to encoding".
std::string LeaveCoresToOtherThreads(int busy_threads, std::size_t triangles);

}  // namespace urdfsnap::gl
