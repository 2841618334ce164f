// LabelRegions: one column-major pass over the label image keeps, per label, its bounding box,
// area and the run lengths of its mask, so all links cost one scan.
#include "dataset/coco_regions.h"

#include <algorithm>
#include <map>

namespace urdfsnap::dataset {

namespace {

struct Runs {
  Region region;
  std::vector<std::int64_t> counts;
  std::int64_t last_change = 0;   // where the current run began
  int x1 = -1, y1 = -1;           // bottom-right pixel so far
};

void Add(Runs& r, int x, int y) {
  if (r.region.area == 0) {
    r.region.x = x;
    r.region.y = y;
  }
  ++r.region.area;
  r.region.x = std::min(r.region.x, x);
  r.region.y = std::min(r.region.y, y);
  r.x1 = std::max(r.x1, x);
  r.y1 = std::max(r.y1, y);
}

// the last run (of ones or zeros) ends with the image, as pycocotools' rleEncode counts it
Region Finish(Runs& r, std::int64_t total) {
  r.counts.push_back(total - r.last_change);
  r.region.width = r.x1 - r.region.x + 1;
  r.region.height = r.y1 - r.region.y + 1;
  r.region.counts = CompressRle(r.counts);
  return r.region;
}

}  // namespace

std::string CompressRle(const std::vector<std::int64_t>& counts) {
  std::string text;
  for (size_t i = 0; i < counts.size(); ++i) {
    std::int64_t x = counts[i];
    if (i > 2) x -= counts[i - 2];   // pycocotools stores the difference from two runs back
    bool more = true;
    while (more) {
      char c = static_cast<char>(x & 0x1f);
      x >>= 5;   // arithmetic shift: negative differences end at −1
      more = (c & 0x10) ? x != -1 : x != 0;
      if (more) c |= 0x20;
      text.push_back(static_cast<char>(c + 48));
    }
  }
  return text;
}

std::vector<Region> LabelRegions(const image::LabelImage& labels) {
  const int w = labels.width, h = labels.height;
  std::map<int, Runs> runs;      // by label
  Runs robot;                    // every non-zero pixel
  int previous = 0;              // the label of the pixel before, column-major
  std::int64_t p = 0;
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y, ++p) {
      const int label = labels.labels[static_cast<size_t>(y) * w + x];
      if (label != previous) {
        // the previous label's run of ones ends here, this label's run of zeros does
        for (const int changed : {previous, label}) {
          if (changed == 0) continue;
          Runs& r = runs[changed];
          r.counts.push_back(p - r.last_change);
          r.last_change = p;
        }
        if ((previous == 0) != (label == 0)) {
          robot.counts.push_back(p - robot.last_change);
          robot.last_change = p;
        }
        previous = label;
      }
      if (label == 0) continue;
      Add(runs[label], x, y);
      Add(robot, x, y);
    }
  }
  std::vector<Region> regions;
  const std::int64_t total = p;
  for (auto& [label, r] : runs) {
    r.region.label = label;
    regions.push_back(Finish(r, total));
  }
  if (robot.region.area > 0) regions.push_back(Finish(robot, total));
  return regions;
}

}  // namespace urdfsnap::dataset
