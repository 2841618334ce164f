// Depth and label files: millimetres and NaN as ROS's 16UC1/32FC1 conventions have them, the .npy
// layout numpy.load reads, the label names and their file, and bad file names (unit).
#include "render/frame_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "common/error.h"
#include "image/npy_writer.h"
#include "image/png_reader.h"
#include "support/temp_folder.h"

namespace urdfsnap::render {
namespace {

constexpr float kNone = NAN;

TEST(FrameFiles, DepthPngHoldsMillimetresAndZeroOffTheRobot) {
  const test::TempFolder folder("frame_files");
  const image::DepthImage depth{3, 2, {kNone, 1.2345f, 0.0002f, 2.0f, 70.0f, 65.535f}};
  EXPECT_EQ(DepthMillimetres(depth).values, (std::vector<std::uint16_t>{0, 1235, 1, 2000, 65535, 65535}));
  const image::Gray16Image read = image::ReadGray16Png(folder.Write("depth.png", DepthFileBytes(depth, "depth.png")));
  EXPECT_EQ(read.width, 3);
  EXPECT_EQ(read.height, 2);
  EXPECT_EQ(read.values, DepthMillimetres(depth).values);
}

TEST(FrameFiles, DepthNpyIsFloat32MetresWithNanInNumpysLayout) {
  const test::TempFolder folder("frame_files");
  const image::DepthImage depth{3, 2, {kNone, 1.5f, 2.25f, 3, 4, 5}};
  const std::string bytes = DepthFileBytes(depth, "out/depth.npy");
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

TEST(FrameFiles, LabelPngAndItsNamesBesideIt) {
  const test::TempFolder folder("frame_files");
  Warnings warnings;
  const model::Robot robot = model::LoadRobot(
      "<robot name=\"r\"><link name=\"base\"/><link name=\"arm\"/><joint name=\"j\" type=\"fixed\">"
      "<parent link=\"base\"/><child link=\"arm\"/></joint></robot>",
      "r.urdf", warnings);
  const image::LabelImage labels{2, 2, {0, 1, 2, 2}};
  EXPECT_EQ(image::ReadGray16Png(folder.Write("labels.png", LabelFileBytes(labels))).values, labels.labels);
  EXPECT_EQ(LabelNamesJson(robot), "{\n  \"1\": \"base\",\n  \"2\": \"arm\"\n}\n");
  EXPECT_EQ(LabelNamesFile("out/seg.labels.png"), "out/seg.labels.json");
}

TEST(FrameFiles, TheApiWritesOneFramesFiles) {
  const test::TempFolder folder("frame_files");
  Warnings warnings;
  const model::Robot robot = model::LoadRobot("<robot name=\"r\"><link name=\"base\"/></robot>", "r.urdf", warnings);
  WriteDepthFile({1, 1, {1.5f}}, folder.Path("d.png"));
  WriteLabelFiles({1, 1, {1}}, robot, folder.Path("l.png"));
  EXPECT_EQ(image::ReadGray16Png(folder.Path("d.png")).values, std::vector<std::uint16_t>{1500});
  EXPECT_EQ(image::ReadGray16Png(folder.Path("l.png")).values, std::vector<std::uint16_t>{1});
  EXPECT_EQ(folder.Read("l.json"), LabelNamesJson(robot));
  EXPECT_THROW(WriteDepthFile({1, 1, {1.0f}}, folder.Path("no/such/folder/d.png")), Error);
  EXPECT_EQ(folder.Listing(), (std::vector<std::string>{"d.png", "l.json", "l.png"}));
}

TEST(FrameFiles, BadNamesAreRefused) {
  try {
    CheckDepthPath("depth.tiff", "--depth");
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--depth 'depth.tiff': expected a .png (16-bit millimetres) or .npy (float32 metres) file");
  }
  EXPECT_THROW(CheckLabelsPath("labels.npy", "--labels"), Error);
  EXPECT_THROW(DepthFileBytes({1, 1, {1.0f}}, "depth.jpg"), Error);
}

}  // namespace
}  // namespace urdfsnap::render
