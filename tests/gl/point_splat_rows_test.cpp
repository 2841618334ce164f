// PointSplat's flat-square covering (gl/internal/point_splat_rows.h): the portable version against
// a texel-by-texel reference, and the AVX2 version (where the CPU has it) against the portable one,
// bit for bit, over random squares with tied depths, within, across and past a tile's edges.
#include "gl/internal/point_splat_rows.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace urdfsnap::gl::point_splat_rows {
namespace {

constexpr int kTile = 32;
constexpr std::size_t kPlane = kTile * kTile;
constexpr int kX0 = 64, kY0 = 32;   // the tile's first pixel

// `samples` samples on the 1/256-pixel grid, padded to four, and empty planes for them
struct Planes {
  explicit Planes(std::size_t samples) : count(samples) {
    std::mt19937 random(7);
    for (std::size_t s = 0; s < (samples + 3) / 4 * 4; ++s) {
      x.push_back(static_cast<float>(random() % 256) / 256.f);
      y.push_back(static_cast<float>(random() % 256) / 256.f);
    }
    for (std::size_t s = 0; s < samples; ++s) {
      texels.insert(texels.end(), kPlane, std::bit_cast<std::uint32_t>(2.f));
      texels.insert(texels.end(), kPlane, 0u);
    }
  }
  std::size_t count;
  std::vector<float> x, y;
  std::vector<std::uint32_t> texels;
};

// Random squares on the 1/256-pixel grid reaching up to 8 pixels past the tile, four depths (ties)
std::vector<Flat> Squares(const Planes& planes, int n) {
  std::mt19937 random(11);
  const auto coordinate = [&](int origin) {
    return static_cast<float>(origin - 8) + static_cast<float>(random() % ((kTile + 16) * 256)) / 256.f;
  };
  const auto held = [](float v, int low) {
    return std::fmin(std::fmax(v, static_cast<float>(low - 2)), static_cast<float>(low + kTile + 2));
  };
  std::vector<Flat> squares;
  for (int i = 0; i < n; ++i) {
    const float x0 = coordinate(kX0), y0 = coordinate(kY0);
    const float side = static_cast<float>(1 + random() % (12 * 256)) / 256.f;
    squares.push_back({planes.x.data(), planes.y.data(), planes.count, kTile, kX0, kY0, kX0 + kTile, kY0 + kTile,
                       held(x0, kX0), held(x0 + side, kX0), held(y0, kY0), held(y0 + side, kY0),
                       0.25f * static_cast<float>(random() % 4), static_cast<std::uint32_t>(i + 1)});
  }
  return squares;
}

// Sample s of a pixel is covered where it lies in [sx0, sx1) x [sy0, sy1) and the square is nearer
void Reference(const Flat& square, std::uint32_t* texels) {
  for (std::size_t s = 0; s < square.samples; ++s) {
    std::uint32_t* depths = texels + 2 * s * kPlane;
    for (int py = 0; py < kTile; ++py) {
      for (int px = 0; px < kTile; ++px) {
        const float x = static_cast<float>(kX0 + px) + square.sample_x[s];
        const float y = static_cast<float>(kY0 + py) + square.sample_y[s];
        const std::size_t texel = static_cast<std::size_t>(py * kTile + px);
        if (x >= square.sx0 && x < square.sx1 && y >= square.sy0 && y < square.sy1 &&
            square.depth <= std::bit_cast<float>(depths[texel])) {
          depths[texel] = std::bit_cast<std::uint32_t>(square.depth);
          depths[kPlane + texel] = square.colour;
        }
      }
    }
  }
}

TEST(PointSplatRowsTest, ThePortableVersionCoversAsTheReferenceDoes) {
  for (std::size_t samples : {1u, 4u, 5u}) {
    Planes portable(samples), reference(samples);
    const std::vector<Flat> squares = Squares(portable, 300);
    for (const Flat& square : squares) CoverPortable(square, portable.texels.data());
    for (const Flat& square : squares) Reference(square, reference.texels.data());
    EXPECT_EQ(portable.texels, reference.texels) << samples << " samples";
    // (the squares covered some of the tile, not all)
    std::size_t covered = 0;
    for (std::size_t t = 0; t < kPlane; ++t) covered += portable.texels[kPlane + t] != 0;
    EXPECT_GT(covered, kPlane / 4);
  }
}

TEST(PointSplatRowsTest, TheAvx2VersionWritesTheSameBitsAsThePortableOne) {
  const CoverFunction avx2 = CoverAvx2();
  if (avx2 == nullptr) GTEST_SKIP() << "this CPU has no AVX2";
  EXPECT_EQ(Cover(), avx2);   // chosen where the CPU has it
  for (std::size_t samples : {1u, 4u, 8u}) {
    Planes portable(samples), vector(samples);
    const std::vector<Flat> squares = Squares(portable, 300);
    for (const Flat& square : squares) CoverPortable(square, portable.texels.data());
    for (const Flat& square : squares) avx2(square, vector.texels.data());
    EXPECT_EQ(portable.texels, vector.texels) << samples << " samples";
  }
}

}  // namespace
}  // namespace urdfsnap::gl::point_splat_rows
