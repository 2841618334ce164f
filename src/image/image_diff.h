// Comparing two images pixel by pixel, for golden-image tests: numbers to judge by and a picture
// that shows where they differ.
#pragma once

#include <cstdint>
#include <string>

#include "image/image.h"

namespace urdfsnap::image {

// A pixel's delta is the largest of its three channel differences (0..255).
struct DiffStats {
  int max_delta = 0;                                   // largest pixel delta
  double mean_delta = 0;                               // mean pixel delta over all pixels
  double fraction_over = 0;                            // pixels_over / pixel count
  int pixels_over = 0;                                 // pixels whose delta exceeds the threshold
  int min_x = -1, min_y = -1, max_x = -1, max_y = -1;  // their bounding box, inclusive; -1 if none
};

// When two renders count as the same picture: the defaults of `urdfsnap diff` and of snapshot
// suites. llvmpipe renders byte-identically run after run and with any thread count. Another
// x86-64 CPU (simulated with GALLIUM_OVERRIDE_CPU_CAPS=sse2, i.e. no AVX; even =nosse) rounds a
// few anti-aliased edge samples differently: measured on mrm at five views, at most 3 pixels over
// a delta of 8 (0.001%) and a mean delta of at most 0.008. A joint of mrm moved by 0.01 rad in the
// default view changes 190-405 pixels by more than 8 (0.06-0.13%), mean 0.024-0.054. The limits
// sit about 10x above the noise and 6x below the smallest joint change; tests/cli/diff_test.cpp
// checks both sides. Thumbnails far smaller than 640x480 may need a larger max_fraction.
struct DiffTolerance {
  int max_delta = 8;             // a pixel counts as changed when a channel differs by more
  double max_fraction = 0.0001;  // images differ when more than this fraction of pixels changed
  double max_mean = 0.1;         // ... or when the mean pixel delta (0..255) is above this
};

// Grows the inclusive bounding box (min_x, min_y, max_x, max_y; all -1 while empty) of `stats`, a
// DiffStats or Gray16DiffStats, by the pixel (x, y).
template <typename Stats>
void GrowRegion(Stats& stats, int x, int y) {
  if (stats.min_x < 0) {
    stats.min_x = stats.max_x = x;
    stats.min_y = stats.max_y = y;
    return;
  }
  stats.min_x = x < stats.min_x ? x : stats.min_x;
  stats.max_x = x > stats.max_x ? x : stats.max_x;
  stats.min_y = y < stats.min_y ? y : stats.min_y;
  stats.max_y = y > stats.max_y ? y : stats.max_y;
}

// The grey (64..127) MakeDiffImage draws an unchanged pixel of colour `rgb` in: its Rec. 601 luma
// squeezed so that no grey comes near the diff colours.
std::uint8_t DimmedGrey(const std::uint8_t* rgb);

// True when `stats` (from CompareImages with tolerance.max_delta) are within `tolerance`.
bool WithinTolerance(const DiffStats& stats, const DiffTolerance& tolerance);

// One line with the figures a decision was made on: "max delta 96, mean delta 0.41, 812 pixels
// (0.264%) over 24 (limit 0.05%), in x 233..301, y 120..274".
std::string DescribeDiff(const DiffStats& stats, const DiffTolerance& tolerance);

// Compares `actual` with `expected`, counting pixels whose delta is over `delta`. Throws
// urdfsnap::Error if either image is inconsistent or their sizes differ (naming both sizes).
DiffStats CompareImages(const Image& expected, const Image& actual, int delta);

// A picture of the difference: pixels whose delta is over `delta` in magenta (255, 0, 255), pixels
// changed by less in yellow (255, 200, 0) (a faint change everywhere fails on the mean delta and
// must show too), the rest a dimmed grey (64..127) copy of `expected` so that the robot's outline
// stays readable.
// Throws like CompareImages.
Image MakeDiffImage(const Image& expected, const Image& actual, int delta);

}  // namespace urdfsnap::image
