// RobotMask: per row, the horizontal distance to the nearest robot pixel; then a disc of radius N
// is a set of row spans, one per vertical offset, so growing the mask costs O(pixels x (2N + 1)).
#include "camera/robot_mask.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace urdfsnap::camera {

image::Gray8Image RobotMask(const image::LabelImage& labels, int dilate) {
  const int w = labels.width, h = labels.height;
  image::Gray8Image mask{w, h, std::vector<std::uint8_t>(labels.labels.size(), 0)};
  if (dilate <= 0) {
    for (size_t i = 0; i < labels.labels.size(); ++i) mask.values[i] = labels.labels[i] != 0 ? 255 : 0;
    return mask;
  }
  // the distance along its row from each pixel to the nearest robot pixel (large: none)
  const int none = std::numeric_limits<int>::max() / 2;
  std::vector<int> across(labels.labels.size(), none);
  for (int y = 0; y < h; ++y) {
    int* row = &across[static_cast<size_t>(y) * w];
    const std::uint16_t* in = &labels.labels[static_cast<size_t>(y) * w];
    int last = none;
    for (int x = 0; x < w; ++x) {
      last = in[x] != 0 ? 0 : std::min(last + 1, none);
      row[x] = last;
    }
    last = none;
    for (int x = w - 1; x >= 0; --x) {
      last = in[x] != 0 ? 0 : std::min(last + 1, none);
      row[x] = std::min(row[x], last);
    }
  }
  // a pixel is in the grown mask when, for some vertical offset dy, the row dy away has a robot
  // pixel within the disc's half-width there
  std::vector<int> half_width(dilate + 1);
  for (int dy = 0; dy <= dilate; ++dy) {
    half_width[dy] = static_cast<int>(std::floor(std::sqrt(double(dilate) * dilate - double(dy) * dy)));
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int y0 = std::max(0, y - dilate), y1 = std::min(h - 1, y + dilate);
      for (int yy = y0; yy <= y1; ++yy) {
        if (across[static_cast<size_t>(yy) * w + x] <= half_width[std::abs(yy - y)]) {
          mask.values[static_cast<size_t>(y) * w + x] = 255;
          break;
        }
      }
    }
  }
  return mask;
}

}  // namespace urdfsnap::camera
