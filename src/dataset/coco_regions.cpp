// LabelRegions: one column-major pass over the label image, a run of equal labels down a column
// at a time, keeps per label (in a table indexed by the label) its bounding box, area and the run
// lengths of its mask, so all links cost one scan and a run costs what one pixel did.
#include "dataset/coco_regions.h"

#include <algorithm>

namespace urdfsnap::dataset {

namespace {

struct Runs {
  Region region;
  std::vector<std::int64_t> counts;
  std::int64_t last_change = 0;   // where the current run began
  int x1 = -1, y1 = -1;           // bottom-right pixel so far
};

// rows [y, end) of column x belong to r's mask
void Add(Runs& r, int x, int y, int end) {
  if (r.region.area == 0) {
    r.region.x = x;
    r.region.y = y;
  }
  r.region.area += end - y;
  r.region.x = std::min(r.region.x, x);
  r.region.y = std::min(r.region.y, y);
  r.x1 = std::max(r.x1, x);
  r.y1 = std::max(r.y1, end - 1);
}

// a run of `r`'s ones or zeros ends before column-major pixel p
void EndRun(Runs& r, std::int64_t p) {
  r.counts.push_back(p - r.last_change);
  r.last_change = p;
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
  std::vector<Runs> runs;        // by label; area 0 for a label not (yet) seen
  Runs robot;                    // every non-zero pixel
  int previous = 0;              // the label of the pixel before, column-major
  for (int x = 0; x < w; ++x) {
    const std::uint16_t* column = labels.labels.data() + x;
    for (int y = 0; y < h;) {
      const int label = column[static_cast<size_t>(y) * w];
      int end = y + 1;
      while (end < h && column[static_cast<size_t>(end) * w] == label) ++end;
      if (label != previous) {
        // the previous label's run of ones ends here, this label's run of zeros does
        const std::int64_t p = static_cast<std::int64_t>(x) * h + y;
        if (label >= static_cast<int>(runs.size())) runs.resize(static_cast<size_t>(label) + 1);
        if (previous != 0) EndRun(runs[previous], p);
        if (label != 0) EndRun(runs[label], p);
        if ((previous == 0) != (label == 0)) EndRun(robot, p);
        previous = label;
      }
      if (label != 0) {
        Add(runs[label], x, y, end);
        Add(robot, x, y, end);
      }
      y = end;
    }
  }
  std::vector<Region> regions;
  const std::int64_t total = static_cast<std::int64_t>(w) * h;
  for (size_t label = 1; label < runs.size(); ++label) {
    Runs& r = runs[label];
    if (r.region.area == 0) continue;
    r.region.label = static_cast<int>(label);
    regions.push_back(Finish(r, total));
  }
  if (robot.region.area > 0) regions.push_back(Finish(robot, total));
  return regions;
}

}  // namespace urdfsnap::dataset
