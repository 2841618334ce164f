// COCO regions of a label image: bounding boxes, areas and pycocotools' compressed RLE, decoded
// here by the inverse of pycocotools' rleFrString and compared with the labels pixel by pixel.
#include <gtest/gtest.h>

#include "dataset/coco_regions.h"

namespace urdfsnap::dataset {
namespace {

// pycocotools' rleFrString: the run lengths of a compressed RLE string
std::vector<std::int64_t> Decompress(const std::string& s) {
  std::vector<std::int64_t> counts;
  for (size_t p = 0; p < s.size();) {
    std::int64_t x = 0;
    int k = 0;
    bool more = true;
    while (more) {
      const int c = s[p++] - 48;
      x |= static_cast<std::int64_t>(c & 0x1f) << (5 * k);
      more = c & 0x20;
      ++k;
      if (!more && (c & 0x10)) x |= ~std::int64_t{0} << (5 * k);
    }
    if (counts.size() > 2) x += counts[counts.size() - 2];
    counts.push_back(x);
  }
  return counts;
}

TEST(CocoRle, CompressesAsPycocotoolsRleToString) {
  // worked by hand from rleToString: 5 bits a character, +48, 0x20 for "more", differences from
  // two runs back after the third, negative ones ending at −1
  EXPECT_EQ(CompressRle({0, 4}), "04");
  EXPECT_EQ(CompressRle({3, 2, 1, 4, 100}), "3212S3");
  EXPECT_EQ(CompressRle({5, 40, 3, 1000, 2}), "5X13Pn0O");
  for (const std::vector<std::int64_t>& counts :
       {std::vector<std::int64_t>{0, 4}, {3, 2, 1, 4, 100}, {5, 40, 3, 1000, 2}, {7, 1, 123456, 2, 0, 99999}}) {
    EXPECT_EQ(Decompress(CompressRle(counts)), counts);
  }
}

TEST(CocoRegions, BoxesAreasAndMasksOfEveryLabel) {
  // 5 wide, 4 high:
  //   0 1 1 0 0
  //   0 1 2 2 0
  //   0 0 2 2 0
  //   3 0 0 0 3
  const image::LabelImage labels{5, 4, {0, 1, 1, 0, 0, 0, 1, 2, 2, 0, 0, 0, 2, 2, 0, 3, 0, 0, 0, 3}};
  const std::vector<Region> regions = LabelRegions(labels);
  ASSERT_EQ(regions.size(), 4u);   // labels 1, 2, 3, then the robot
  const int expected_box[4][4] = {{1, 0, 2, 2}, {2, 1, 2, 2}, {0, 3, 5, 1}, {0, 0, 5, 4}};
  const int expected_area[4] = {3, 4, 2, 9};
  for (int r = 0; r < 4; ++r) {
    const Region& region = regions[r];
    EXPECT_EQ(region.label, r < 3 ? r + 1 : 0);
    EXPECT_EQ(region.area, expected_area[r]);
    EXPECT_EQ((std::vector<int>{region.x, region.y, region.width, region.height}),
              std::vector<int>(expected_box[r], expected_box[r] + 4));
    // the runs, column by column, rebuild exactly the pixels of the label
    const std::vector<std::int64_t> counts = Decompress(region.counts);
    std::vector<bool> mask;
    for (size_t i = 0; i < counts.size(); ++i) mask.insert(mask.end(), counts[i], i % 2 == 1);
    ASSERT_EQ(mask.size(), 20u);
    for (int x = 0; x < 5; ++x) {
      for (int y = 0; y < 4; ++y) {
        const int label = labels.labels[y * 5 + x];
        EXPECT_EQ(mask[x * 4 + y], region.label == 0 ? label != 0 : label == region.label) << r << " " << x << "," << y;
      }
    }
  }
}

TEST(CocoRegions, AnEmptyImageHasNone) {
  EXPECT_TRUE(LabelRegions({3, 2, std::vector<std::uint16_t>(6, 0)}).empty());
}

}  // namespace
}  // namespace urdfsnap::dataset
