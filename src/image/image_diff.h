// Comparing two images pixel by pixel, for golden-image tests: numbers to judge by and a picture
// that shows where they differ.
#pragma once

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

// Compares `actual` with `expected`, counting pixels whose delta is over `delta`. Throws
// urdfsnap::Error if either image is inconsistent or their sizes differ (naming both sizes).
DiffStats CompareImages(const Image& expected, const Image& actual, int delta);

// A picture of the difference: pixels whose delta is over `delta` in magenta (255, 0, 255), the
// rest a dimmed grey (64..127) copy of `expected` so that the robot's outline stays readable.
// Throws like CompareImages.
Image MakeDiffImage(const Image& expected, const Image& actual, int delta);

}  // namespace urdfsnap::image
