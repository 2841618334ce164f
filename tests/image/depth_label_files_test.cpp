// Depth and label files: millimetres and NaN as ROS's 16UC1/32FC1 conventions have them, the .npy
// layout numpy.load reads, the label names beside the label image, and bad file names (unit).
#include "image/depth_label_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "image/image_file_names.h"
#include "image/npy_writer.h"
#include "image/png_reader.h"
#include "support/error_text.h"
#include "support/temp_folder.h"

namespace urdfsnap::image {
namespace {

constexpr float kNone = NAN;

std::string Contents(const std::string& path) {
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}

TEST(DepthLabelFiles, DepthPngHoldsMillimetresAndZeroOffTheRobot) {
  const test::TempFolder folder("frame_files");
  const DepthImage depth{3, 2, {kNone, 1.2345f, 0.0002f, 2.0f, 70.0f, 65.535f}};
  EXPECT_EQ(DepthMillimetres(depth).values, (std::vector<std::uint16_t>{0, 1235, 1, 2000, 65535, 65535}));
  WriteDepthFile(depth, folder.Path("depth.png"));
  const Gray16Image read = ReadGray16Png(folder.Path("depth.png"));
  EXPECT_EQ(read.width, 3);
  EXPECT_EQ(read.height, 2);
  EXPECT_EQ(read.values, DepthMillimetres(depth).values);
}

TEST(DepthLabelFiles, DepthNpyIsFloat32MetresWithNanInNumpysLayout) {
  const test::TempFolder folder("frame_files");
  const DepthImage depth{3, 2, {kNone, 1.5f, 2.25f, 3, 4, 5}};
  WriteDepthFile(depth, folder.Path("depth.npy"));
  const std::string bytes = Contents(folder.Path("depth.npy"));
  ASSERT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const size_t header_length = static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8;
  EXPECT_EQ((10 + header_length) % 64, 0u);   // the data start 64-byte aligned
  const std::string header = bytes.substr(10, header_length);
  EXPECT_EQ(header.rfind("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", 0), 0u) << header;
  EXPECT_EQ(header.back(), '\n');
  ASSERT_EQ(bytes.size(), 10 + header_length + 6 * sizeof(float));
  float values[6];
  std::memcpy(values, bytes.data() + 10 + header_length, sizeof values);
  EXPECT_TRUE(std::isnan(values[0]));
  EXPECT_EQ(values[2], 2.25f);
  EXPECT_EQ(values[5], 5.0f);
}

TEST(DepthLabelFiles, LabelPngAndItsNamesBesideIt) {
  const test::TempFolder folder("frame_files");
  const LabelImage labels{2, 2, {0, 1, 2, 2}};
  WriteLabelFiles(labels, {"base", "arm"}, folder.Path("labels.png"));
  EXPECT_EQ(ReadGray16Png(folder.Path("labels.png")).values, labels.labels);
  EXPECT_EQ(Contents(folder.Path("labels.json")), "{\n  \"1\": \"base\",\n  \"2\": \"arm\"\n}\n");
}

TEST(DepthLabelFiles, BadNamesAreRefusedBeforeAnythingIsWritten) {
  const test::TempFolder folder("frame_files");
  try {
    CheckImageFileName("depth.tiff", ImageKind::kDepth, "--depth");
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--depth 'depth.tiff': expected a .png (16-bit millimetres) or .npy (float32 metres) "
                           "file; urdfsnap does not write .tiff images");
  }
  EXPECT_THROW(CheckImageFileName("labels.npy", ImageKind::kLabels, "--labels"), Error);
  EXPECT_NO_THROW(CheckImageFileName("DEPTH.NPY", ImageKind::kDepth, "--depth"));
  EXPECT_THROW(WriteLabelFiles({1, 1, {0}}, {}, folder.Path("labels.jpg")), Error);
  EXPECT_THROW(WriteDepthFile({1, 1, {1.0f}}, folder.Path("no/such/folder/depth.png")), Error);
  EXPECT_TRUE(folder.Listing().empty());
}

TEST(DepthLabelFiles, TheExtensionChoosesTheDepthEncoding) {
  const test::TempFolder folder("depth_encoding");
  const DepthImage depth{2, 1, {kNone, 1.5f}};
  for (const std::string extension : {".png", ".npy"}) {
    WriteDepthFile(depth, folder.Path("depth" + extension));
    EXPECT_EQ(EncodeDepthFile(depth, folder.Path("depth" + extension)), Contents(folder.Path("depth" + extension))) << extension;
  }
  EXPECT_EQ(EncodeDepthFile(depth, "d.npy").substr(0, 6), "\x93NUMPY");
  EXPECT_EQ(EncodeDepthFile(depth, "depth/%05d.png").substr(1, 3), "PNG");
  EXPECT_EQ(test::ErrorText([&] { EncodeDepthFile(depth, "d.tiff"); }),
            "depth file 'd.tiff': expected a .png (16-bit millimetres) or .npy (float32 metres) file; urdfsnap "
            "does not write .tiff images");
}

TEST(DepthLabelFiles, LabelNamesGoBesideTheLabelImage) {
  EXPECT_EQ(LabelNamesFile("out/seg.labels.png"), "out/seg.labels.json");
}

}  // namespace
}  // namespace urdfsnap::image
