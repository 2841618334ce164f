// The per-link regions of a label image as COCO annotates objects: bounding box, area and the
// mask as run-length encoding (RLE), in pycocotools' compressed string form: runs counted down the
// columns (column-major, as pycocotools' masks are Fortran-ordered), starting with a run of zeros,
// each count written as pycocotools' rleToString writes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace urdfsnap::dataset {

struct Region {
  int label = 0;              // the label image's value (1 + link index); 0 for the whole robot
  std::int64_t area = 0;      // pixels
  int x = 0, y = 0;           // bounding box: the top-left pixel's column and row, and the size in
  int width = 0, height = 0;  // pixels (COCO's [x, y, width, height] with pixel i spanning [i, i + 1))
  std::string counts;         // compressed RLE of the mask
};

// One region per label value present in `labels` (in increasing value), then, when any is
// present, the whole robot's (label 0: every non-zero pixel).
std::vector<Region> LabelRegions(const image::LabelImage& labels);

// pycocotools' rleToString of run lengths `counts` (zeros first).
std::string CompressRle(const std::vector<std::int64_t>& counts);

}  // namespace urdfsnap::dataset
