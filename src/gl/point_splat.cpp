// PointSplat: each point projected as shaders/point.vert and point_quad.vert place it, its square
// covered sample by sample, coloured as shaders/point.frag colours it.
#include "gl/internal/point_splat.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>
#include <cmath>
#include <optional>
#include <system_error>
#include <thread>

namespace urdfsnap::gl {

namespace {

// GL's conversion of a colour channel to 8 bits (round to nearest)
std::uint32_t Byte(float value) { return static_cast<std::uint32_t>(std::clamp(value, 0.f, 1.f) * 255.f + 0.5f); }

std::uint32_t Pack(const Eigen::Vector4f& rgba) {
  return Byte(rgba[0]) | Byte(rgba[1]) << 8 | Byte(rgba[2]) << 16 | Byte(rgba[3]) << 24;
}

// The two roundings llvmpipe snaps window coordinates to 1/256 pixel with (lp_setup's FIXED_ORDER
// 8), without a libm call. A triangle's vertices: the SSE conversion of calc_fixed_position
// (lp_setup_tri.c), to nearest with ties to even; adding and taking away 1.5 * 2^23 leaves that
// for |v| < 2^22.
float SnapVertex(float v) {
  constexpr float kMagic = 12582912.f;
  v *= 256.f;
  return (std::abs(v) < 4194304.f ? (v + kMagic) - kMagic : std::nearbyint(v)) * (1.f / 256.f);
}
// A GL point's centre and size (lp_setup_point.c's subpixel_snap): util_iround, which on x86-64
// adds or takes away a half in float and truncates (u_math.h), in 1/256 pixel
// (v finite; held to a billion, 3.9 million pixels, so that adding a size stays within int)
int SnapPoint(float v) {
  v = std::clamp(v * 256.f, -1e9f, 1e9f);
  return static_cast<int>(v >= 0.f ? v + 0.5f : v - 0.5f);
}

float Smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// shaders/point.frag at square coordinates (u, v) in [0, 1]; false where the disc discards
bool Shade(int shape, float u, float v, Eigen::Vector3f& c) {
  const float ax = u - 0.5f, ay = v - 0.5f;
  if (shape == 1) {
    const float blend = Smoothstep(-0.48f, -0.45f, ay) * (1.f - Smoothstep(0.45f, 0.48f, ay)) *
                        Smoothstep(-0.48f, -0.45f, ax) * (1.f - Smoothstep(0.45f, 0.48f, ax));
    const float sign = c.norm() < 0.5f ? 1.f : c.norm() > 0.5f ? -1.f : 0.f;
    c = blend * c + (Eigen::Vector3f::Constant(sign * 0.2f) + c) * (1.f - blend);
  } else if (shape == 2) {
    const float a = (0.25f - (ax * ax + ay * ay)) * 4.f;
    if (a <= 0.f) return false;
    c = 0.8f * c + (c - 0.8f * c) * a;
  }
  return true;
}

// Four lanes of ints or floats, GCC's (and Clang's) vector extension: SSE2 on x86-64.
using Lanes = std::int32_t __attribute__((vector_size(16)));
using Floats = float __attribute__((vector_size(16)));

// a where `mask` is set, else b
Lanes Select(Lanes mask, Lanes a, Lanes b) { return (a & mask) | (b & ~mask); }
Lanes Max(Lanes a, int b) { return Select(a > b, a, Lanes{} + b); }
Lanes Min(Lanes a, int b) { return Select(a < b, a, Lanes{} + b); }

// Ceil for four values well within int
Lanes CeilWithin(Floats v) {
  const Lanes i = __builtin_convertvector(v, Lanes);
  return i - (__builtin_convertvector(i, Floats) < v);   // a true lane is -1
}

// Ceil for four values at once, any held at a million pixels (a square reaching far off the screen)
Lanes Ceil(Floats v) {
  const Floats low = Floats{} - 1e6f, high = Floats{} + 1e6f;
  v = std::bit_cast<Floats>(Select(v < low, std::bit_cast<Lanes>(low), std::bit_cast<Lanes>(v)));
  v = std::bit_cast<Floats>(Select(v > high, std::bit_cast<Lanes>(high), std::bit_cast<Lanes>(v)));
  return CeilWithin(v);
}

// Covers columns [first, end) of rows [row0, row1) of one sample's depths and colours (planes of
// kTileSize x kTileSize) at `depth` with `colour` where that is nearer (GL_LEQUAL): four columns a
// vector from `first`, the last four of a row at most; a lane out of [first, end) or farther keeps
// its value. No branch on the depth test: which of two points is nearer is a coin toss in a cloud.
void CoverRows(std::uint32_t* depths, std::uint32_t* colours, int first, int end, int row0, int row1, float depth,
               std::uint32_t colour) {
  const Lanes column{0, 1, 2, 3};
  const Floats near = Floats{} + depth;
  const Lanes bits = Lanes{} + std::bit_cast<std::int32_t>(depth);
  const Lanes packed = Lanes{} + static_cast<std::int32_t>(colour);
  for (int x = first; x < end; x += 4) {
    const int window = std::min(x, PointSplat::kTileSize - 4);
    const Lanes at = column + window;
    const Lanes columns = (at >= x) & (at < end);
    for (int row = row0; row < row1; ++row) {
      const std::size_t texel = static_cast<std::size_t>(row) * PointSplat::kTileSize + static_cast<std::size_t>(window);
      Floats old_depth;
      Lanes old_colour;
      std::memcpy(&old_depth, depths + texel, sizeof old_depth);
      std::memcpy(&old_colour, colours + texel, sizeof old_colour);
      const Lanes in = columns & (near <= old_depth);
      const Lanes new_depth = Select(in, bits, std::bit_cast<Lanes>(old_depth));
      const Lanes new_colour = Select(in, packed, old_colour);
      std::memcpy(depths + texel, &new_depth, sizeof new_depth);
      std::memcpy(colours + texel, &new_colour, sizeof new_colour);
    }
  }
}

}  // namespace

void PointSplat::Clear(int width, int height, const std::vector<Eigen::Vector2f>& samples) {
  width_ = width;
  height_ = height;
  tiles_x_ = (width + kTileSize - 1) / kTileSize;
  tiles_y_ = (height + kTileSize - 1) / kTileSize;
  samples_ = samples;
  sample_min_ = sample_max_ = samples.front();
  for (const Eigen::Vector2f& s : samples) sample_min_ = sample_min_.cwiseMin(s), sample_max_ = sample_max_.cwiseMax(s);
  // their extent in 1/256 pixel, when the samples lie on that grid (GL's standard positions do)
  const auto on_grid = [](const Eigen::Vector2f& s) { return (s * 256.f).array().round().matrix() == s * 256.f; };
  fixed_samples_ = std::all_of(samples.begin(), samples.end(), on_grid);
  fixed_sample_min_ = (sample_min_ * 256.f).cast<int>(), fixed_sample_max_ = (sample_max_ * 256.f).cast<int>();
  sample_x_.assign((samples.size() + 3) / 4 * 4, samples.front().x());
  sample_y_.assign(sample_x_.size(), samples.front().y());
  for (std::size_t s = 0; s < samples.size(); ++s) sample_x_[s] = samples[s].x(), sample_y_[s] = samples[s].y();
  // no pass over the image: a tile is emptied when a square first reaches it in a frame
  planes_.resize(static_cast<std::size_t>(tiles_x_) * tiles_y_ * TileWords());
  kept_used_ = 0;
  next_order_ = 0;
  drawn_.clear();
}

PointSplat::Tile PointSplat::TileAt(int tile) const {
  const int x0 = tile % tiles_x_ * kTileSize, y0 = tile / tiles_x_ * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width_), std::min(y0 + kTileSize, height_)};
}

PointSplat::Texel PointSplat::At(int x, int y, int s) const {
  const int tile = y / kTileSize * tiles_x_ + x / kTileSize;
  if (!std::binary_search(drawn_.begin(), drawn_.end(), tile)) return {kEmpty, 0};
  const std::uint32_t* depths = planes_.data() + static_cast<std::size_t>(tile) * TileWords() + 2 * static_cast<std::size_t>(s) * kPlane;
  const std::size_t texel = static_cast<std::size_t>(y % kTileSize) * kTileSize + x % kTileSize;
  return {std::bit_cast<float>(depths[texel]), depths[kPlane + texel]};
}

PointSplat::Pixels PointSplat::Reach(float x0, float x1, float y0, float y1) const {
  // x in [x0, x1) is pixel column px in [ceil(x0 - sx), ceil(x1 - sx)) for a sample at sx
  const Lanes c = Ceil(Floats{x0 - sample_max_.x(), x1 - sample_min_.x(), y0 - sample_max_.y(), y1 - sample_min_.y()});
  return {std::max(0, c[0]), std::min(width_, c[1]) - 1, std::max(0, c[2]), std::min(height_, c[3]) - 1};
}

void PointSplat::Keep(Kept& kept, const Square& square) const {
  // llvmpipe snaps each vertex (lp_setup_tri.c)
  Square snapped = square;
  snapped.x0 = SnapVertex(square.x0), snapped.x1 = SnapVertex(square.x1);
  snapped.y0 = SnapVertex(square.y0), snapped.y1 = SnapVertex(square.y1);
  KeepSnapped(kept, snapped);
}

void PointSplat::KeepPoint(Kept& kept, float x, float y, float size, float depth, std::uint32_t rgba8,
                           std::uint32_t order) const {
  if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(depth))) return;   // GL would draw nothing either
  // lp_setup_point.c: the size in fixed point, at least a pixel; x0 = snapped centre - size / 2 (an
  // integer division), x1 = x0 + size
  const int fixed = std::max(SnapPoint(size >= 0.f ? std::min(size, 1e6f) : 0.f), 256);   // (not a number: a pixel)
  const int x0 = SnapPoint(x) - fixed / 2, y0 = SnapPoint(y) - fixed / 2;
  const auto pixels = [](int fixed_point) { return static_cast<float>(fixed_point) * (1.f / 256.f); };
  const Square square{pixels(x0), pixels(x0 + fixed), pixels(y0), pixels(y0 + fixed), depth, rgba8, order, 0};
  if (!fixed_samples_) {
    KeepSnapped(kept, square);
    return;
  }
  // Reach in whole numbers: ceil(v / 256) is (v + 255) >> 8, the shift rounding down
  const auto ceil = [](int v) { return (v + 255) >> 8; };
  KeepReaching(kept, square,
               {std::max(0, ceil(x0 - fixed_sample_max_.x())), std::min(width_, ceil(x0 + fixed - fixed_sample_min_.x())) - 1,
                std::max(0, ceil(y0 - fixed_sample_max_.y())), std::min(height_, ceil(y0 + fixed - fixed_sample_min_.y())) - 1});
}

void PointSplat::KeepSnapped(Kept& kept, Square square) const {
  if (!(std::isfinite(square.x0) && std::isfinite(square.x1) && std::isfinite(square.y0) && std::isfinite(square.y1) &&
        std::isfinite(square.depth))) {
    return;   // a point at infinity: GL would draw nothing either
  }
  KeepReaching(kept, square, Reach(square.x0, square.x1, square.y0, square.y1));
}

void PointSplat::KeepReaching(Kept& kept, Square square, const Pixels& pixels) const {
  if (pixels.px0 > pixels.px1 || pixels.py0 > pixels.py1) return;
  const int tx0 = pixels.px0 / kTileSize, tx1 = pixels.px1 / kTileSize;
  const int ty0 = pixels.py0 / kTileSize, ty1 = pixels.py1 / kTileSize;
  const int tile = ty0 * tiles_x_ + tx0;
  square.reach |= static_cast<std::uint32_t>(tile);
  if (tx1 - tx0 > 1 || ty1 - ty0 > 1) {
    kept.big.push_back(square);   // kept once (Bin)
    return;
  }
  std::uint32_t* const counts = kept.counts.data();
  ++counts[tile];
  if (tx1 > tx0) square.reach |= Square::kWide, ++counts[tile + 1];
  if (ty1 > ty0) {
    square.reach |= Square::kHigh, ++counts[tile + tiles_x_];
    if (tx1 > tx0) ++counts[tile + tiles_x_ + 1];
  }
  kept.squares.push_back(square);
}

void PointSplat::CoverSquare(const Square& square, const Tile& tile, std::uint32_t* planes) const {
  const std::size_t count = samples_.size();
  // sample s's depth and colour planes, each kTileSize x kTileSize
  const auto plane = [&](std::size_t s, int which) { return planes + (2 * s + which) * kPlane; };
  if (square.shape() == 0) {
    // one colour: each sample's own rows and columns of pixels whose sample lies inside, where x
    // in [x0, x1) is px in [ceil(x0 - sx), ceil(x1 - sx)); four samples' bounds at a time, the
    // square first held to the tile and a pixel either side (the same pixels within the tile)
    const auto held = [](float v, int low, int high) {
      return std::clamp(v, static_cast<float>(low - 2), static_cast<float>(high + 2));
    };
    const float x0 = held(square.x0, tile.x0, tile.x1), x1 = held(square.x1, tile.x0, tile.x1);
    const float y0 = held(square.y0, tile.y0, tile.y1), y1 = held(square.y1, tile.y0, tile.y1);
    for (std::size_t first = 0; first < count; first += 4) {
      Floats sx, sy;
      std::memcpy(&sx, sample_x_.data() + first, sizeof sx);
      std::memcpy(&sy, sample_y_.data() + first, sizeof sy);
      const Lanes px0 = Max(CeilWithin(x0 - sx), tile.x0) - tile.x0;
      const Lanes px1 = Min(CeilWithin(x1 - sx), tile.x1) - tile.x0;
      const Lanes py0 = Max(CeilWithin(y0 - sy), tile.y0) - tile.y0;
      const Lanes py1 = Min(CeilWithin(y1 - sy), tile.y1) - tile.y0;
      for (std::size_t k = 0; k < 4 && first + k < count; ++k) {
        CoverRows(plane(first + k, 0), plane(first + k, 1), px0[k], px1[k], py0[k], py1[k], square.depth, square.rgba8);
      }
    }
    return;
  }
  // shaded: the colour at each pixel's centre, for the samples of the pixel inside the square
  const Eigen::Vector3f flat(static_cast<float>(square.rgba8 & 0xff) / 255.f,
                             static_cast<float>(square.rgba8 >> 8 & 0xff) / 255.f,
                             static_cast<float>(square.rgba8 >> 16 & 0xff) / 255.f);
  const std::uint32_t alpha = square.rgba8 & 0xff000000u;
  const Pixels pixels = Reach(square.x0, square.x1, square.y0, square.y1);
  for (int py = std::max(pixels.py0, tile.y0); py <= std::min(pixels.py1, tile.y1 - 1); ++py) {
    for (int px = std::max(pixels.px0, tile.x0); px <= std::min(pixels.px1, tile.x1 - 1); ++px) {
      Eigen::Vector3f c = flat;
      const float u = (static_cast<float>(px) + 0.5f - square.x0) / (square.x1 - square.x0);
      const float v = (static_cast<float>(py) + 0.5f - square.y0) / (square.y1 - square.y0);
      if (!Shade(square.shape(), u, v, c)) continue;
      const std::uint32_t packed = Byte(c[0]) | Byte(c[1]) << 8 | Byte(c[2]) << 16 | alpha;
      const std::size_t texel = static_cast<std::size_t>(py - tile.y0) * kTileSize + static_cast<std::size_t>(px - tile.x0);
      for (std::size_t s = 0; s < count; ++s) {
        const float x = static_cast<float>(px) + samples_[s].x(), y = static_cast<float>(py) + samples_[s].y();
        // a sample on the left or lower edge is in, on the right or upper one out: what llvmpipe's
        // fill rule gives in urdfsnap's flipped framebuffer (the GL-drawn goldens agree)
        if (!(x >= square.x0 && x < square.x1 && y >= square.y0 && y < square.y1)) continue;
        std::uint32_t& depth = plane(s, 0)[texel];
        if (!(square.depth <= std::bit_cast<float>(depth))) continue;
        depth = std::bit_cast<std::uint32_t>(square.depth);
        plane(s, 1)[texel] = packed;
      }
    }
  }
}

void PointSplat::NextKept() {
  if (kept_used_ == kept_.size()) kept_.emplace_back();
  Kept& kept = kept_[kept_used_++];
  kept.squares.clear();
  kept.big.clear();
  kept.counts.assign(static_cast<std::size_t>(tiles_x_) * tiles_y_, 0);
}

std::size_t PointSplat::KeptSquares() const {
  std::size_t squares = 0;
  for (std::size_t k = 0; k < kept_used_; ++k) squares += kept_[k].squares.size() + kept_[k].big.size();
  return squares;
}

template <typename Work>
void PointSplat::OnTwoThreads(bool two, const Work& work) {
  std::optional<std::thread> helper;
  if (two && std::thread::hardware_concurrency() > 1) {
    try {
      helper.emplace([&work] { work(1); });
    } catch (const std::system_error&) {
      // no thread to be had: this one does both
    }
  }
  work(0);
  if (helper) {
    helper->join();
  } else if (two) {
    work(1);
  }
}

void PointSplat::Bin() {
  // a stable counting sort of copies of the squares by tile (a tile's squares keep their order),
  // so that covering a tile reads its squares in a row rather than from all over the kept ones;
  // Keep counted them, and kept those reaching more tiles than one of kTileSize pixels can (2 x 2)
  // aside, so that the copies stay within four a square however big the squares are
  const std::size_t tiles = static_cast<std::size_t>(tiles_x_) * tiles_y_;
  std::vector<char> reached(tiles, 0);
  big_.clear();
  for (std::size_t k = 0; k < kept_used_; ++k) {
    for (const Square& square : kept_[k].big) {
      big_.push_back(square);
      const Pixels pixels = Reach(square.x0, square.x1, square.y0, square.y1);
      for (int ty = pixels.py0 / kTileSize; ty <= pixels.py1 / kTileSize; ++ty) {
        for (int tx = pixels.px0 / kTileSize; tx <= pixels.px1 / kTileSize; ++tx) reached[ty * tiles_x_ + tx] = 1;
      }
    }
  }
  // tile t's squares from kept_[0], then kept_[1]'s, ...
  tile_starts_.assign(tiles + 1, 0);
  for (std::size_t k = 0; k < kept_used_; ++k) kept_[k].next.resize(tiles);
  for (std::size_t t = 0; t < tiles; ++t) {
    std::uint32_t start = tile_starts_[t];
    for (std::size_t k = 0; k < kept_used_; ++k) kept_[k].next[t] = start, start += kept_[k].counts[t];
    tile_starts_[t + 1] = start;
    if (reached[t] || start > tile_starts_[t]) drawn_.push_back(static_cast<int>(t));
  }
  binned_.resize(tile_starts_[tiles]);
  OnTwoThreads(KeptSquares() >= kSquaresPerThread, [&](std::size_t thread) {
    for (std::size_t k = thread; k < kept_used_; k += 2) {
      std::vector<std::uint32_t>& next = kept_[k].next;
      for (const Square& square : kept_[k].squares) {
        const int tile = square.tile();
        binned_[next[tile]++] = square;
        if (square.reach & Square::kWide) binned_[next[tile + 1]++] = square;
        if (square.reach & Square::kHigh) {
          binned_[next[tile + tiles_x_]++] = square;
          if (square.reach & Square::kWide) binned_[next[tile + tiles_x_ + 1]++] = square;
        }
      }
    }
  });
}

void PointSplat::CoverTile(int tile, std::uint32_t* texels) {
  std::uint32_t* const planes = planes_.data() + static_cast<std::size_t>(tile) * TileWords();
  for (std::size_t s = 0; s < samples_.size(); ++s) {
    std::fill_n(planes + 2 * s * kPlane, kPlane, std::bit_cast<std::uint32_t>(kEmpty));
    std::fill_n(planes + (2 * s + 1) * kPlane, kPlane, 0u);
  }
  // the tile's own squares and the big ones that reach it, merged in the order they were added
  const Tile rect = TileAt(tile);
  const Square* small = binned_.data() + tile_starts_[tile];
  const Square* const small_end = binned_.data() + tile_starts_[tile + 1];
  const Square* big = big_.data();
  const Square* const big_end = big + big_.size();
  while (small < small_end || big < big_end) {
    if (big == big_end || (small < small_end && small->order < big->order)) {
      CoverSquare(*small++, rect, planes);
    } else if (const Pixels pixels = Reach(big->x0, big->x1, big->y0, big->y1);
               pixels.px1 < rect.x0 || pixels.px0 >= rect.x1 || pixels.py1 < rect.y0 || pixels.py0 >= rect.y1) {
      ++big;
    } else {
      CoverSquare(*big++, rect, planes);
    }
  }
  if (texels == nullptr) return;
  // each sample's depth and colour planes, interleaved as (depth, colour) pairs
  std::uint32_t* out = texels + static_cast<std::size_t>(tile) * TileWords();
  for (std::size_t s = 0; s < samples_.size(); ++s) {
    const std::uint32_t* depths = planes + 2 * s * kPlane;
    const std::uint32_t* colours = depths + kPlane;
    for (std::size_t i = 0; i < kPlane; ++i) out[2 * i] = depths[i], out[2 * i + 1] = colours[i];
    out += 2 * kPlane;
  }
}

void PointSplat::Cover(std::uint32_t* texels) {
  Bin();
  // the tiles taken in turn by this thread and, with many squares, a second one
  std::atomic<std::size_t> next{0};
  OnTwoThreads(KeptSquares() >= kSquaresPerThread, [&](std::size_t) {
    for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < drawn_.size();) CoverTile(drawn_[i], texels);
  });
}

void PointSplat::Add(const scene::PointSet& points, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P) {
  const std::size_t n = std::min(points.positions.size(), points.colours.size());
  const Eigen::Matrix4f MV = V.cast<float>(), Pf = P.cast<float>();
  const std::uint32_t first_order = next_order_;
  next_order_ += static_cast<std::uint32_t>(n);
  // a big set's second half projected on a second thread, into a Kept of its own after the first's
  const bool two = n >= 2 * kSquaresPerThread;
  const std::size_t first_kept = kept_used_, mid = two ? n / 2 : n;
  NextKept();
  if (two) NextKept();   // (kept_ may grow: its elements are taken after)
  OnTwoThreads(two, [&](std::size_t half) {
    Project(points, MV, Pf, half == 0 ? 0 : mid, half == 0 ? mid : n, first_order, kept_[first_kept + half]);
  });
}

void PointSplat::Project(const scene::PointSet& points, const Eigen::Matrix4f& MV, const Eigen::Matrix4f& P,
                         std::size_t first, std::size_t last, std::uint32_t first_order, Kept& kept) const {
  using Style = scene::PointSet::Style;
  const Eigen::Matrix4f MVP = P * MV;
  const float half_width = 0.5f * static_cast<float>(width_), half_height = 0.5f * static_cast<float>(height_);
  // window x, y and depth of a clip-space position as Mesa's draw module maps it (draw_llvm.c's
  // generate_viewport: times 1 / w, then the viewport's scale and translation), so that two points
  // at nearly one depth tie or not as they do in GL
  const auto window = [&](const Eigen::Vector4f& clip) {
    const float iw = 1.f / clip.w();
    return Eigen::Vector3f(clip.x() * iw * half_width + half_width, clip.y() * iw * half_height + half_height,
                           clip.z() * iw * 0.5f + 0.5f);
  };
  const std::uint32_t shape = points.style == Style::kSquares ? 1 : points.style == Style::kSpheres ? 2 : 0;
  const float half = 0.5f * points.size.x();   // pixels for Points, metres for the squares
  for (std::size_t i = first; i < last; ++i) {
    const std::uint32_t rgba8 = Pack(points.colours[i]);   // the 8-bit vertex colour
    const auto order = static_cast<std::uint32_t>(first_order + i);
    const Eigen::Vector4f p(points.positions[i].x(), points.positions[i].y(), points.positions[i].z(), 1.f);
    if (points.style == Style::kPoints) {
      // a GL point: clipped by its centre, a square of point_size pixels (at least one)
      const Eigen::Vector4f clip = MVP * p;
      if (!(std::abs(clip.x()) <= clip.w() && std::abs(clip.y()) <= clip.w() && std::abs(clip.z()) <= clip.w())) continue;
      const Eigen::Vector3f w = window(clip);
      KeepPoint(kept, w.x(), w.y(), points.size.x(), w.z(), rgba8, order);
    } else {
      // a camera-facing square: corners moved from the centre in the image plane, clipped near/far
      const Eigen::Vector4f centre = MV * p;
      const Eigen::Vector4f clip = P * centre;
      if (!(std::abs(clip.z()) <= clip.w())) continue;
      const Eigen::Vector3f low = window(P * (centre + Eigen::Vector4f(-half, -half, 0, 0)));
      const Eigen::Vector3f high = window(P * (centre + Eigen::Vector4f(half, half, 0, 0)));
      Keep(kept, {low.x(), high.x(), low.y(), high.y(), window(clip).z(), rgba8, order, shape << Square::kShapeShift});
    }
  }
}

}  // namespace urdfsnap::gl
