// Comparing two 16-bit images pixel by pixel, for the depth and link-label goldens of snapshot
// suites and `urdfsnap diff --depth/--labels`: depth in millimetres with a tolerance of its own,
// labels exactly (up to a small fraction of edge pixels); a value of 0 (no robot there) never
// matches a value other than 0. And the pictures that make them visible in a report: the files
// hold millimetres and link numbers, which look black as they are.
#pragma once

#include <string>

#include "image/image.h"

namespace urdfsnap::image {

// What is stored in the 16-bit image: it decides how values are compared and described.
enum class Gray16Kind {
  kDepth,   // millimetres, 0 where no robot is: pixels within max_delta mm of each other match
  kLabels,  // 1 + link index, 0 where none: only equal values match
};

struct Gray16DiffStats {
  int max_delta = 0;        // depth: the largest difference in mm where both have robot; labels: 0
  int pixels_over = 0;      // pixels that differ: by more than max_delta, or robot in one image only
  int pixels_coverage = 0;  // of those, the pixels with robot (a value other than 0) in one image only
  double fraction_over = 0; // pixels_over / pixel count
  int min_x = -1, min_y = -1, max_x = -1, max_y = -1;  // the bounding box of pixels_over; -1 if none
};

// When two depth or label images count as the same. Measured at 640x480 on mrm (five views) and
// four other robots (tests/data looks, its collision geometry, texbot, meshbot): a re-render for
// another x86-64 CPU (GALLIUM_OVERRIDE_CPU_CAPS=sse2 or sse4.1, i.e. no AVX) moves depth by at most
// 1 mm (the rounding to whole millimetres) on at most 25 pixels (0.008%), and no pixel by more;
// the EGL backend renders both images identically to OSMesa; no label changes at all. A joint of
// mrm moved by 0.01 rad in the default view changes depth by more than 2 mm on 741-2080 pixels
// (0.24-0.68%) and labels on 38-123 pixels (0.012-0.040%). So depth allows 2 mm (twice the noise)
// on 0.01% of the pixels, 24x below the smallest joint change; labels are compared exactly.
// tests/cli/snapshot_depth_test.cpp checks both sides.
struct Gray16Tolerance {
  int max_delta = 0;         // depth: a pixel differs when its millimetres differ by more; labels: 0
  double max_fraction = 0;   // the images differ when more than this fraction of pixels differ
};

// The defaults of suite cases with depth or labels goldens.
Gray16Tolerance DefaultTolerance(Gray16Kind kind);

// Compares `actual` with `expected`. Throws urdfsnap::Error if either image is inconsistent
// (size outside 1..kMaxImageSide, value count) or their sizes differ (naming both sizes).
// For kLabels, `max_delta` must be 0.
Gray16DiffStats CompareGray16(const Gray16Image& expected, const Gray16Image& actual, Gray16Kind kind,
                              int max_delta);

bool WithinTolerance(const Gray16DiffStats& stats, const Gray16Tolerance& tolerance);

// One line with the figures: "max delta 12 mm, 340 pixels (0.111%) over 3 mm (limit 0.05%), 52 of
// them robot in one image only, in x 233..301, y 120..274" (depth) or "340 pixels (0.111%) differ
// (limit 0%), 52 of them robot in one image only, in x ..." (labels).
std::string DescribeGray16Diff(const Gray16DiffStats& stats, const Gray16Tolerance& tolerance, Gray16Kind kind);

// A viewable picture of a depth image: robot pixels coloured from yellow (near) through green and
// blue to dark purple (far) over the range [near_mm, far_mm]; black where no robot is. Give the
// expected and actual images of a comparison the same range (Gray16ValueRange of both) so that
// equal colours mean equal depths.
Image DepthPicture(const Gray16Image& depth, int near_mm, int far_mm);

// The smallest and largest value other than 0 in `a` and `b` (1, 1 when there is none).
void Gray16ValueRange(const Gray16Image& a, const Gray16Image& b, int& low, int& high);

// A viewable picture of a label image: one distinct colour per label (the same colour for the same
// link in every picture), black where none.
Image LabelPicture(const Gray16Image& labels);

// Where two 16-bit images differ: magenta (255, 0, 255) where a pixel differs beyond `max_delta`
// with robot in both, cyan (0, 255, 255) where robot is in one image only, yellow (255, 200, 0)
// where values differ within the tolerance, elsewhere a dimmed grey of `expected_picture` (the
// DepthPicture or LabelPicture of `expected`). Throws like CompareGray16.
Image MakeGray16DiffImage(const Gray16Image& expected, const Gray16Image& actual, int max_delta,
                          const Image& expected_picture);

}  // namespace urdfsnap::image
