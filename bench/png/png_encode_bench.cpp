// PNG encoding of a 640x480 robot-like frame: stb_image_write as shipped (its own deflate at level
// 8, best of five row filters per row) against urdfsnap's EncodePng (zlib level 1, no row filter),
// plus the step between them and the whole WritePng to disk. Counters give the file size, so that
// the speed-up can be seen not to cost size.
// usage: urdfsnap_png_bench [Google Benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "image/png_writer.h"

// a private copy of stb_image_write with its defaults, for the baseline
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

namespace {

using urdfsnap::image::Image;

// What a render looks like to a compressor: RViz's grey background, one-pixel grid lines in
// perspective, and Gouraud-shaded red links (smooth gradients with anti-aliased edges).
Image RobotLikeFrame() {
  constexpr int kWidth = 640, kHeight = 480;
  Image image{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight * 3, 48)};
  const auto blend = [&](int x, int y, float coverage, float r, float g, float b) {
    std::uint8_t* p = &image.rgb[3 * (y * kWidth + x)];
    p[0] = std::uint8_t(std::lround(p[0] + coverage * (r - p[0])));
    p[1] = std::uint8_t(std::lround(p[1] + coverage * (g - p[1])));
    p[2] = std::uint8_t(std::lround(p[2] + coverage * (b - p[2])));
  };
  // grid: lines converging towards a vanishing point above the image, and horizontal lines
  for (int i = -5; i <= 5; ++i) {
    for (int y = 200; y < kHeight; ++y) {
      const float x = 320 + i * (y - 120) * 0.45f;
      const int xi = int(std::floor(x));
      if (xi < 0 || xi + 1 >= kWidth) continue;
      blend(xi, y, 1 - (x - xi), 104, 104, 106);
      blend(xi + 1, y, x - xi, 104, 104, 106);
    }
    const int y = 300 + i * 16 + i * i * 2;
    for (int x = 40; x < 600; ++x) blend(x, y, 1, 104, 104, 106);
  }
  // links: a box and three upright cylinders, shaded by the cosine of the surface angle
  const auto cylinder = [&](int cx, int top, int bottom, int radius) {
    for (int y = top; y < bottom; ++y) {
      for (int x = cx - radius - 1; x <= cx + radius + 1; ++x) {
        const float u = float(x - cx) / radius;
        const float coverage = std::clamp(radius + 0.5f - std::abs(float(x - cx)), 0.f, 1.f);
        const float shade = std::sqrt(std::max(0.f, 1 - u * u));
        blend(x, y, coverage, 255 * (0.35f + 0.6f * shade), 0, 0);
      }
    }
  };
  for (int y = 300; y < 420; ++y) {
    for (int x = 220; x < 420; ++x) blend(x, y, 1, 150 + (x - 220) / 4, 0, 0);
  }
  cylinder(320, 230, 300, 70);
  cylinder(320, 120, 230, 30);
  cylinder(360, 40, 120, 30);
  return image;
}

// stb's own deflate at level 8 with row filter -1 (its default: best of five per row) or 0 (none:
// how much of the gain is the filter search alone)
void BM_Stb(benchmark::State& state) {
  const Image frame = RobotLikeFrame();
  stbi_write_force_png_filter = int(state.range(0));
  int size = 0;
  for (auto _ : state) {
    unsigned char* png = stbi_write_png_to_mem(frame.rgb.data(), 640 * 3, 640, 480, 3, &size);
    benchmark::DoNotOptimize(png);
    std::free(png);
  }
  state.counters["bytes"] = size;
}

void BM_UrdfsnapEncodePng(benchmark::State& state) {
  const Image frame = RobotLikeFrame();
  std::size_t size = 0;
  for (auto _ : state) {
    const std::vector<std::uint8_t> png = urdfsnap::image::EncodePng(frame);
    benchmark::DoNotOptimize(png.data());
    size = png.size();
  }
  state.counters["bytes"] = double(size);
}

// encoding plus the temporary file and rename, into the system temp folder
void BM_UrdfsnapWritePng(benchmark::State& state) {
  const Image frame = RobotLikeFrame();
  const std::string path =
      (std::filesystem::temp_directory_path() / "urdfsnap_png_bench.png").string();
  for (auto _ : state) urdfsnap::image::WritePng(frame, path);
  state.counters["bytes"] = double(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}

BENCHMARK(BM_Stb)->ArgName("filter")->Arg(-1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_UrdfsnapEncodePng)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_UrdfsnapWritePng)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
