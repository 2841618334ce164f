// PNG writing and reading: exact round trips with top-row-first order, colour-type conversion on
// reading, and refusal of files that are not PNGs or claim an absurd size.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "image/gray16_png.h"
#include "image/png_reader.h"
#include "image/png_writer.h"
#include "support/temp_folder.h"

namespace urdfsnap::image {
namespace {

using Bytes = std::vector<std::uint8_t>;

void AppendBigEndian32(Bytes& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(value >> shift));
}

void AppendChunk(Bytes& out, const char* type, const Bytes& data) {
  AppendBigEndian32(out, std::uint32_t(data.size()));
  Bytes body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  out.insert(out.end(), body.begin(), body.end());
  AppendBigEndian32(out, std::uint32_t(crc32(0, body.data(), uInt(body.size()))));
}

// A PNG made by hand, independent of the code under test: colour type 0 grey, 2 RGB, 6 RGBA;
// samples of `bit_depth` bits given row by row (top first) without filter bytes. An empty
// `samples` leaves out the image data, for header-only files.
Bytes HandMadePng(std::uint32_t width, std::uint32_t height, int colour_type,
                  const Bytes& samples, int bit_depth = 8) {
  Bytes png = {137, 80, 78, 71, 13, 10, 26, 10};
  Bytes header;
  AppendBigEndian32(header, width);
  AppendBigEndian32(header, height);
  header.insert(header.end(), {std::uint8_t(bit_depth), std::uint8_t(colour_type), 0, 0, 0});
  AppendChunk(png, "IHDR", header);
  if (!samples.empty()) {
    const std::size_t row = samples.size() / height;
    Bytes filtered;
    for (std::uint32_t y = 0; y < height; ++y) {
      filtered.push_back(0);
      filtered.insert(filtered.end(), samples.begin() + y * row, samples.begin() + (y + 1) * row);
    }
    uLongf size = compressBound(uLong(filtered.size()));
    Bytes deflated(size);
    EXPECT_EQ(compress(deflated.data(), &size, filtered.data(), uLong(filtered.size())), Z_OK);
    deflated.resize(size);
    AppendChunk(png, "IDAT", deflated);
  }
  AppendChunk(png, "IEND", {});
  return png;
}

// A 3x2 image with a different colour in every pixel, so that swapped rows or columns show.
Image SmallImage() {
  return {3,
          2,
          {255, 0, 0, 0, 255, 0, 0, 0, 255,  //
           1, 2, 3, 250, 251, 252, 48, 48, 48}};
}

class PngIoTest : public testing::Test {
 protected:
  std::string Path(const std::string& name) const { return folder_.Path(name); }
  std::vector<std::string> Listing() const { return folder_.Listing(); }
  test::TempFolder folder_{"image_test"};

  void WriteBytes(const std::string& path, const Bytes& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  }
  std::string ReadError(const Bytes& file_bytes) {
    const std::string path = Path("input.png");
    WriteBytes(path, file_bytes);
    try {
      ReadPng(path);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(PngIoTest, RoundTripIsExact) {
  const std::string path = Path("out.png");
  WritePng(SmallImage(), path);
  const Image read = ReadPng(path);
  EXPECT_EQ(read.width, 3);
  EXPECT_EQ(read.height, 2);
  EXPECT_EQ(read.rgb, SmallImage().rgb);
  EXPECT_EQ(Listing(), std::vector<std::string>{"out.png"});
}

TEST_F(PngIoTest, EncodedRowsAreTopFirst) {
  // read back by hand: the first row of samples in the stream is the image's top row
  const Bytes png = EncodePng(SmallImage());
  const Bytes hand = HandMadePng(3, 2, 2, SmallImage().rgb);
  WriteBytes(Path("hand.png"), hand);
  EXPECT_EQ(ReadPng(Path("hand.png")).rgb, SmallImage().rgb);
  WriteBytes(Path("ours.png"), png);
  EXPECT_EQ(ReadPng(Path("ours.png")).rgb, SmallImage().rgb);
  // same header as the hand-made file: signature, IHDR with 3x2, 8-bit RGB
  EXPECT_TRUE(std::equal(hand.begin(), hand.begin() + 33, png.begin()));
}

// The speed of EncodePng comes from skipping stb's per-row filter search: every row must carry
// filter type 0 in the deflated image data.
TEST(PngWriterTest, RowFilterIsOff) {
  // a ramp, which stb's search would encode with the "sub" filter
  Image ramp{16, 2, Bytes(16 * 2 * 3)};
  for (std::size_t i = 0; i < ramp.rgb.size(); ++i) ramp.rgb[i] = std::uint8_t(i * 5);
  const Bytes png = EncodePng(ramp);
  Bytes deflated;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length =
        std::uint32_t(png[at]) << 24 | png[at + 1] << 16 | png[at + 2] << 8 | png[at + 3];
    if (std::equal(png.begin() + at + 4, png.begin() + at + 8, "IDAT")) {
      deflated.insert(deflated.end(), png.begin() + at + 8, png.begin() + at + 8 + length);
    }
    at += 12 + length;
  }
  Bytes rows(2 * (1 + 16 * 3));
  uLongf size = uLongf(rows.size());
  ASSERT_EQ(uncompress(rows.data(), &size, deflated.data(), uLong(deflated.size())), Z_OK);
  ASSERT_EQ(size, rows.size());
  EXPECT_EQ(rows[0], 0);
  EXPECT_EQ(rows[1 + 16 * 3], 0);
}

// The 16-bit grey PNGs (depth, labels) are framed by gray16_png.cpp itself: checked here against
// zlib, independently of libdeflate, as strict readers (libpng) check them: the same signature and
// header as a hand-made file, every chunk's CRC, IDAT inflating to filter-0 rows of big-endian
// samples, IEND last.
TEST(Gray16PngWriterTest, ChunksAreWhatPngSaysWithValidCrcs) {
  const Gray16Image image{3, 2, {0, 1, 0x1234, 65535, 1500, 0xABCD}};
  const Bytes png = EncodeGray16Png(image);
  Bytes samples;
  for (std::uint16_t value : image.values) samples.insert(samples.end(), {std::uint8_t(value >> 8), std::uint8_t(value)});
  const Bytes hand = HandMadePng(3, 2, 0, samples, 16);
  ASSERT_GE(png.size(), 33u);
  EXPECT_TRUE(std::equal(hand.begin(), hand.begin() + 33, png.begin()));
  std::vector<std::string> types;
  Bytes deflated;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::uint32_t length =
        std::uint32_t(png[at]) << 24 | png[at + 1] << 16 | png[at + 2] << 8 | png[at + 3];
    ASSERT_LE(at + 12 + length, png.size());
    types.emplace_back(png.begin() + at + 4, png.begin() + at + 8);
    const std::size_t end = at + 8 + length;
    const std::uint32_t crc = std::uint32_t(png[end]) << 24 | png[end + 1] << 16 | png[end + 2] << 8 | png[end + 3];
    EXPECT_EQ(crc, crc32(0, png.data() + at + 4, uInt(length + 4))) << types.back();
    if (types.back() == "IDAT") deflated.insert(deflated.end(), png.begin() + at + 8, png.begin() + end);
    at = end + 4;
  }
  EXPECT_EQ(at, png.size());
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
  Bytes rows(2 * (1 + 3 * 2) + 1);
  uLongf size = uLongf(rows.size());
  ASSERT_EQ(uncompress(rows.data(), &size, deflated.data(), uLong(deflated.size())), Z_OK);
  rows.resize(size);
  const Bytes expected = {0, 0, 0, 0, 1, 0x12, 0x34, 0, 0xFF, 0xFF, 0x05, 0xDC, 0xAB, 0xCD};
  EXPECT_EQ(rows, expected);
}

TEST_F(PngIoTest, LargeImageRoundTrip) {
  Image image{640, 480, Bytes(640 * 480 * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = std::uint8_t(i * 7 / 5);
  WritePng(image, Path("big.png"));
  EXPECT_EQ(ReadPng(Path("big.png")).rgb, image.rgb);
}

TEST_F(PngIoTest, GreyBecomesRgb) {
  WriteBytes(Path("grey.png"), HandMadePng(2, 1, 0, {10, 200}));
  const Image image = ReadPng(Path("grey.png"));
  EXPECT_EQ(image.rgb, (Bytes{10, 10, 10, 200, 200, 200}));
}

TEST_F(PngIoTest, RgbaLosesAlpha) {
  WriteBytes(Path("rgba.png"), HandMadePng(2, 1, 6, {1, 2, 3, 0, 4, 5, 6, 255}));
  const Image image = ReadPng(Path("rgba.png"));
  EXPECT_EQ(image.rgb, (Bytes{1, 2, 3, 4, 5, 6}));
}

TEST_F(PngIoTest, RefusesHugeDimensionsBeforeDecoding) {
  // only a header: if the reader believed it, it would allocate 30 GB
  const std::string message = ReadError(HandMadePng(100000, 100000, 2, {}));
  EXPECT_EQ(message,
            Path("input.png") + ": PNG is 100000x100000 pixels; at most 16384x16384 is read");
}

TEST_F(PngIoTest, RefusesTooManyDecodedBytesBeforeDecoding) {
  // within the side limit, but 16-bit RGBA would need 2 GiB of samples while decoding
  EXPECT_EQ(ReadError(HandMadePng(16384, 16384, 6, {}, 16)),
            Path("input.png") + ": PNG of 16384x16384 pixels at 8 bytes per pixel is too large " +
                "to decode (limit 1024 MiB of samples)");
}

TEST_F(PngIoTest, RefusesImageDataTooShortForTheClaimedSize) {
  // the largest render's size, 8-bit RGB, is allowed, but 805 MB of pixels cannot come from a
  // header without image data: refused before stb allocates the image
  EXPECT_EQ(ReadError(HandMadePng(16384, 16384, 2, {})),
            Path("input.png") + ": PNG claims 16384x16384 pixels but holds 0 bytes of image " +
                "data, too few for that many");
}

TEST_F(PngIoTest, RefusesColourTypesPngDoesNotHave) {
  EXPECT_EQ(ReadError(HandMadePng(4, 4, 5, {})),
            Path("input.png") + ": not a valid PNG (colour type 5 with bit depth 8)");
}

TEST_F(PngIoTest, DecodesFromMemoryWithTheNameGiven) {
  const Bytes png = HandMadePng(3, 2, 2, SmallImage().rgb);
  const Image image = DecodePng(
      std::string_view(reinterpret_cast<const char*>(png.data()), png.size()), "memory.png");
  EXPECT_EQ(image.rgb, SmallImage().rgb);
  EXPECT_THROW(DecodePng("not a png", "memory.png"), Error);
}

TEST_F(PngIoTest, RefusesWhatIsNotPng) {
  const std::string text = "<robot name='r'/>";
  EXPECT_EQ(ReadError(Bytes(text.begin(), text.end())),
            Path("input.png") + ": not a PNG file (no PNG signature)");
  EXPECT_EQ(ReadError({}), Path("input.png") + ": not a PNG file (no PNG signature)");
}

TEST_F(PngIoTest, ReportsCorruptData) {
  Bytes png = HandMadePng(3, 2, 2, SmallImage().rgb);
  png[43] ^= 0xff;  // a byte of the deflate data (after the IDAT header and zlib header)
  EXPECT_EQ(ReadError(png).rfind(Path("input.png") + ": cannot decode PNG: ", 0), 0u)
      << ReadError(png);
}

TEST_F(PngIoTest, RefusesAChunkLongerThanTheFile) {
  Bytes png = HandMadePng(3, 2, 2, SmallImage().rgb);
  png.resize(png.size() - 20);  // cut into the image data
  EXPECT_EQ(ReadError(png).rfind(Path("input.png") + ": PNG chunk at byte 33 claims ", 0), 0u)
      << ReadError(png);
  // found by fuzzing: 60 bytes whose chunk claims 1.4 GB, which stb allocated before reading
  const std::string path =
      std::string(URDFSNAP_SOURCE_DIR) + "/tests/fuzz/png_reader/regression-chunk-longer-than-file.png";
  try {
    ReadPng(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": PNG chunk at byte 33 claims 1380864785 bytes; the file ends before");
  }
}

TEST_F(PngIoTest, ReportsCorruptDataStbGivesNoReasonFor) {
  // found by fuzzing: stb fails on this file without setting a reason, which was read as a null
  // C string
  const std::string path =
      std::string(URDFSNAP_SOURCE_DIR) + "/tests/fuzz/png_reader/regression-no-failure-reason.png";
  try {
    ReadPng(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot decode PNG: corrupt image data");
  }
}

TEST_F(PngIoTest, ReportsMissingFile) {
  try {
    ReadPng(Path("missing.png"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              Path("missing.png") + ": cannot read: No such file or directory");
  }
}

TEST(PngWriterTest, RefusesInconsistentImage) {
  EXPECT_THROW(EncodePng({2, 2, Bytes(11)}), Error);
  EXPECT_THROW(EncodePng({0, 0, {}}), Error);
  try {
    EncodePng({2, 2, Bytes(11)});
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "EncodePng: a 2x2 RGB image needs 12 bytes, got 11");
  }
}

TEST_F(PngIoTest, WritePngNamesThePath) {
  const Image image{1, 1, {1, 2, 3}};
  try {
    WritePng(image, Path("missing/out.png"));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              Path("missing/out.png") + ": cannot write: No such file or directory");
  }
}

}  // namespace
}  // namespace urdfsnap::image
