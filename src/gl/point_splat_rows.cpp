// PointSplat's flat-square covering in two widths: one template written once over the vector
// type, compiled for plain x86-64 (SSE2) and, as a second function, for AVX2 (GCC's target
// attribute), the AVX2 one taken where __builtin_cpu_supports says the CPU has it. Only compares,
// selects, loads and stores per texel, so the two write the same bits.
#include "gl/internal/point_splat_rows.h"

#include <algorithm>
#include <cstring>

namespace urdfsnap::gl::point_splat_rows {

namespace {

// The int and float vectors of Width lanes
template <int Width>
struct Vectors;
template <>
struct Vectors<4> {
  using Ints = Lanes;
  using Reals = Floats;
};
template <>
struct Vectors<8> {
  using Ints = std::int32_t __attribute__((vector_size(32)));
  using Reals = float __attribute__((vector_size(32)));
};

// Covers columns [first, end) of rows [row0, row1) of one sample's depth and colour planes: Width
// columns a vector from `first`, the last Width of a row at most; a lane out of [first, end) or
// farther keeps its value. No branch on the depth test: which of two points is nearer is a coin
// toss in a cloud.
template <int Width>
[[gnu::always_inline]] inline void CoverRows(std::uint32_t* depths, std::uint32_t* colours, int size, int first, int end,
                                             int row0, int row1, float depth, std::uint32_t colour) {
  using Ints = typename Vectors<Width>::Ints;
  using Reals = typename Vectors<Width>::Reals;
  Ints column;
  for (int i = 0; i < Width; ++i) column[i] = i;
  const Reals near = Reals{} + depth;
  const Ints bits = Ints{} + std::bit_cast<std::int32_t>(depth);
  const Ints packed = Ints{} + static_cast<std::int32_t>(colour);
  for (int x = first; x < end; x += Width) {
    const int window = std::min(x, size - Width);
    const Ints at = column + window;
    const Ints columns = (at >= x) & (at < end);
    for (int row = row0; row < row1; ++row) {
      const std::size_t texel = static_cast<std::size_t>(row) * static_cast<std::size_t>(size) + static_cast<std::size_t>(window);
      Reals old_depth;
      Ints old_bits, old_colour;   // (old_bits: old_depth's bits)
      std::memcpy(&old_depth, depths + texel, sizeof old_depth);
      std::memcpy(&old_bits, depths + texel, sizeof old_bits);
      std::memcpy(&old_colour, colours + texel, sizeof old_colour);
      const Ints in = columns & (near <= old_depth);
      // where `in`, the square's, else the old (no call: a 32-byte vector passes only within AVX)
      const Ints new_depth = (bits & in) | (old_bits & ~in);
      const Ints new_colour = (packed & in) | (old_colour & ~in);
      std::memcpy(depths + texel, &new_depth, sizeof new_depth);
      std::memcpy(colours + texel, &new_colour, sizeof new_colour);
    }
  }
}

// Each sample's own rows and columns of pixels whose sample lies inside, where x in [x0, x1) is
// px in [ceil(x0 - sx), ceil(x1 - sx)): four samples' bounds at a time.
template <int Width>
[[gnu::always_inline]] inline void CoverFlat(const Flat& square, std::uint32_t* planes) {
  const std::size_t plane = static_cast<std::size_t>(square.tile_size) * static_cast<std::size_t>(square.tile_size);
  for (std::size_t first = 0; first < square.samples; first += 4) {
    Floats sx, sy;
    std::memcpy(&sx, square.sample_x + first, sizeof sx);
    std::memcpy(&sy, square.sample_y + first, sizeof sy);
    const Lanes px0 = Max(CeilWithin(square.sx0 - sx), square.x0) - square.x0;
    const Lanes px1 = Min(CeilWithin(square.sx1 - sx), square.x1) - square.x0;
    const Lanes py0 = Max(CeilWithin(square.sy0 - sy), square.y0) - square.y0;
    const Lanes py1 = Min(CeilWithin(square.sy1 - sy), square.y1) - square.y0;
    for (std::size_t k = 0; k < 4 && first + k < square.samples; ++k) {
      std::uint32_t* const depths = planes + 2 * (first + k) * plane;
      CoverRows<Width>(depths, depths + plane, square.tile_size, px0[k], px1[k], py0[k], py1[k], square.depth,
                       square.colour);
    }
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] void CoverFlatAvx2(const Flat& square, std::uint32_t* planes) { CoverFlat<8>(square, planes); }
#endif

}  // namespace

void CoverPortable(const Flat& square, std::uint32_t* planes) { CoverFlat<4>(square, planes); }

CoverFunction CoverAvx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  if (__builtin_cpu_supports("avx2")) return CoverFlatAvx2;
#endif
  return nullptr;
}

CoverFunction Cover() {
  static const CoverFunction chosen = CoverAvx2() != nullptr ? CoverAvx2() : CoverPortable;
  return chosen;
}

}  // namespace urdfsnap::gl::point_splat_rows
