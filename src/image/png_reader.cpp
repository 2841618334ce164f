// PNG decoding: the size check on the IHDR chunk, then stb_image compiled here, privately
// (STB_IMAGE_STATIC), for PNG only.
#include "image/png_reader.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "common/error.h"
#include "common/file_reading.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384  // stb's own guard, the same as kMaxImageSide
#include <stb/stb_image.h>

namespace urdfsnap::image {
namespace {

static_assert(STBI_MAX_DIMENSIONS == kMaxImageSide);

std::uint32_t BigEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// Samples per pixel in the file for an IHDR colour type (grey, RGB, palette index, grey + alpha,
// RGBA); 0 for a colour type PNG does not have.
int ChannelsInFile(int colour_type) {
  switch (colour_type) {
    case 0: return 1;
    case 2: return 3;
    case 3: return 1;
    case 4: return 2;
    case 6: return 4;
    default: return 0;
  }
}

// Bytes per pixel stb holds while decoding: palette images are expanded to RGBA, 16-bit samples
// kept at 16 bits until the end.
int DecodedBytesPerPixel(int colour_type, int bit_depth) {
  return colour_type == 3 ? 4 : ChannelsInFile(colour_type) * (bit_depth == 16 ? 2 : 1);
}

// The summed length of the IDAT chunks up to IEND. Refuses a chunk that claims more bytes than
// the file has left: stb allocates a chunk's stated length before reading it (found by fuzzing:
// a 60-byte file made it allocate 1.4 GB).
std::uint64_t ImageDataBytes(const std::string& path, const std::uint8_t* bytes, std::size_t size) {
  std::uint64_t total = 0;
  for (std::size_t at = 8; at + 8 <= size;) {
    const std::uint64_t length = BigEndian32(&bytes[at]);
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    if (type == "IEND") break;
    if (at + 12 + length > size) {
      throw Error(path + ": PNG chunk at byte " + std::to_string(at) + " claims " +
                  std::to_string(length) + " bytes; the file ends before");
    }
    if (type == "IDAT") total += length;
    at += 12 + length;  // length, type, data, CRC
  }
  return total;
}

// A PNG starts with an 8-byte signature and then the IHDR chunk: length 13, "IHDR", width and
// height as big-endian 32-bit numbers, bit depth, colour type. Refuses, before stb allocates
// anything (stb allocates the whole image from the header first): what is not a PNG; more than
// kMaxImageSide pixels a side; more than kMaxDecodedBytes of samples while decoding; and image
// data too short to inflate to the pixels the header claims (deflate shrinks at most 1032:1).
void CheckPngHeader(const std::string& path, const std::uint8_t* bytes, std::size_t size) {
  static constexpr std::array<std::uint8_t, 8> kSignature = {137, 80, 78, 71, 13, 10, 26, 10};
  static constexpr std::uint64_t kMaxDecodedBytes = std::uint64_t{kMaxImageSide} * kMaxImageSide * 4;
  static constexpr std::uint64_t kMaxDeflateRatio = 1032;
  if (size < kSignature.size() || std::memcmp(bytes, kSignature.data(), kSignature.size()) != 0) {
    throw Error(path + ": not a PNG file (no PNG signature)");
  }
  if (size < 26 || BigEndian32(&bytes[8]) != 13 || std::memcmp(&bytes[12], "IHDR", 4)) {
    throw Error(path + ": not a PNG file (no IHDR chunk after the signature)");
  }
  const std::uint32_t width = BigEndian32(&bytes[16]);
  const std::uint32_t height = BigEndian32(&bytes[20]);
  const int bit_depth = bytes[24];
  const int colour_type = bytes[25];
  const std::string size_text = std::to_string(width) + "x" + std::to_string(height);
  if (width > kMaxImageSide || height > kMaxImageSide) {
    throw Error(path + ": PNG is " + size_text + " pixels; at most " +
                std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide) + " is read");
  }
  const int channels = ChannelsInFile(colour_type);
  if (channels == 0 || !(bit_depth == 1 || bit_depth == 2 || bit_depth == 4 || bit_depth == 8 ||
                         bit_depth == 16)) {
    throw Error(path + ": not a valid PNG (colour type " + std::to_string(colour_type) +
                " with bit depth " + std::to_string(bit_depth) + ")");
  }
  const int bytes_per_pixel = DecodedBytesPerPixel(colour_type, bit_depth);
  if (std::uint64_t{width} * height * bytes_per_pixel > kMaxDecodedBytes) {
    throw Error(path + ": PNG of " + size_text + " pixels at " + std::to_string(bytes_per_pixel) +
                " bytes per pixel is too large to decode (limit " +
                std::to_string(kMaxDecodedBytes >> 20) + " MiB of samples)");
  }
  const std::uint64_t row_bytes = (std::uint64_t{width} * channels * bit_depth + 7) / 8;
  const std::uint64_t data_bytes = ImageDataBytes(path, bytes, size);
  if ((data_bytes + 1) * kMaxDeflateRatio < row_bytes * height) {
    throw Error(path + ": PNG claims " + size_text + " pixels but holds " +
                std::to_string(data_bytes) + " bytes of image data, too few for that many");
  }
}

}  // namespace

namespace {

std::string ReadPngFile(const std::string& path) {
  try {
    return ReadFileBounded(path, kMaxPngFileBytes);
  } catch (const FileReadError& e) {
    throw Error(path + ": cannot read: " + e.what());
  }
}

// Decodes with stb after the header checks: `load` is stbi_load_from_memory or its 16-bit twin,
// asked for `channels` channels; `width` and `height` receive the size.
template <typename Load>
auto DecodeChecked(std::string_view bytes, const std::string& path, int channels, int& width, int& height,
                   Load load) {
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  CheckPngHeader(path, data, bytes.size());
  if (bytes.size() > kMaxPngFileBytes) throw Error(path + ": PNG file over 512 MiB");
  int channels_in_file = 0;
  // stb keeps the reason of the last failure (per thread) and sets none for some corrupt data:
  // clear it, so that a message never carries an earlier file's reason
  stbi__g_failure_reason = nullptr;
  auto* pixels = load(data, static_cast<int>(bytes.size()), &width, &height, &channels_in_file, channels);
  if (pixels == nullptr) {
    // no reason is a null C string (found by fuzzing)
    const char* reason = stbi_failure_reason();
    throw Error(path + ": cannot decode PNG: " + (reason ? reason : "corrupt image data"));
  }
  using Sample = std::remove_pointer_t<decltype(pixels)>;
  std::vector<Sample> samples(pixels, pixels + std::size_t(width) * height * channels);
  stbi_image_free(pixels);
  return samples;
}

}  // namespace

Image ReadPng(const std::string& path) { return DecodePng(ReadPngFile(path), path); }

Image DecodePng(std::string_view bytes, const std::string& path) {
  Image image;
  // asking for 3 channels makes stb expand grey, drop alpha and reduce 16-bit samples
  image.rgb = DecodeChecked(bytes, path, 3, image.width, image.height, stbi_load_from_memory);
  return image;
}

Gray16Image ReadGray16Png(const std::string& path) { return DecodeGray16Png(ReadPngFile(path), path); }

Gray16Image DecodeGray16Png(std::string_view bytes, const std::string& path) {
  Gray16Image image;
  // one 16-bit channel: 8-bit files are scaled up (x257), colour is turned grey
  image.values = DecodeChecked(bytes, path, 1, image.width, image.height, stbi_load_16_from_memory);
  return image;
}

}  // namespace urdfsnap::image
