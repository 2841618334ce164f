// The inner loop of PointSplat's covering, one flat (one-colour) square over one tile's samples,
// and the vector helpers it shares with PointSplat. Two versions with bit-identical results: a
// portable one of four columns a vector (SSE2 on x86-64) and, on x86-64 CPUs that have it, one in
// AVX2 of eight (a tile row of 32 pixels is four vectors); Cover() picks one once.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace urdfsnap::gl::point_splat_rows {

// Four lanes of ints or floats, GCC's (and Clang's) vector extension: SSE2 on x86-64.
using Lanes = std::int32_t __attribute__((vector_size(16)));
using Floats = float __attribute__((vector_size(16)));

// a where `mask` is set, else b
[[gnu::always_inline]] inline Lanes Select(Lanes mask, Lanes a, Lanes b) { return (a & mask) | (b & ~mask); }
[[gnu::always_inline]] inline Lanes Max(Lanes a, int b) { return Select(a > b, a, Lanes{} + b); }
[[gnu::always_inline]] inline Lanes Min(Lanes a, int b) { return Select(a < b, a, Lanes{} + b); }

// Ceil for four values well within int
[[gnu::always_inline]] inline Lanes CeilWithin(Floats v) {
  const Lanes i = __builtin_convertvector(v, Lanes);
  return i - (__builtin_convertvector(i, Floats) < v);   // a true lane is -1
}

// One flat square to cover within one tile of `tile_size` x `tile_size` pixels (a multiple of 8)
struct Flat {
  // the samples' positions within a pixel, `samples` of them, each array padded to a multiple of 4
  const float* sample_x;
  const float* sample_y;
  std::size_t samples;
  int tile_size;
  int x0, y0, x1, y1;   // the tile's pixels [x0, x1) x [y0, y1)
  // the square [sx0, sx1) x [sy0, sy1) in window coordinates, held to the tile and a pixel either side
  float sx0, sx1, sy0, sy1;
  float depth;
  std::uint32_t colour;
};
// Covers, in each sample's planes of depths then colours (sample s's at planes + 2 * s *
// tile_size^2), the samples inside the square at its depth with its colour where that is nearer
// (GL_LEQUAL); the rest keep their values.
using CoverFunction = void (*)(const Flat& square, std::uint32_t* planes);
void CoverPortable(const Flat& square, std::uint32_t* planes);
// The AVX2 version, or null where the CPU (or the compiler's target) has none.
CoverFunction CoverAvx2();
// The fastest version this CPU runs (chosen once).
CoverFunction Cover();

}  // namespace urdfsnap::gl::point_splat_rows
