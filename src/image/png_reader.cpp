// PNG decoding: the size check on the IHDR chunk, then stb_image compiled here, privately
// (STB_IMAGE_STATIC), for PNG only.
#include "image/png_reader.h"

#include <array>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

#include "common/error.h"

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

std::vector<std::uint8_t> ReadFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read: " + std::system_category().message(errno));
  std::vector<std::uint8_t> bytes(std::istreambuf_iterator<char>(in), {});
  if (in.bad()) throw Error(path + ": cannot read: " + std::system_category().message(errno));
  return bytes;
}

std::uint32_t BigEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// A PNG starts with an 8-byte signature and then the IHDR chunk: length 13, "IHDR", width and
// height as big-endian 32-bit numbers. Refuses what is not a PNG or is too large to decode.
void CheckPngHeader(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  static constexpr std::array<std::uint8_t, 8> kSignature = {137, 80, 78, 71, 13, 10, 26, 10};
  if (bytes.size() < kSignature.size() ||
      std::memcmp(bytes.data(), kSignature.data(), kSignature.size()) != 0) {
    throw Error(path + ": not a PNG file (no PNG signature)");
  }
  if (bytes.size() < 24 || BigEndian32(&bytes[8]) != 13 || std::memcmp(&bytes[12], "IHDR", 4)) {
    throw Error(path + ": not a PNG file (no IHDR chunk after the signature)");
  }
  const std::uint32_t width = BigEndian32(&bytes[16]);
  const std::uint32_t height = BigEndian32(&bytes[20]);
  if (width > kMaxImageSide || height > kMaxImageSide) {
    throw Error(path + ": PNG is " + std::to_string(width) + "x" + std::to_string(height) +
                " pixels; at most " + std::to_string(kMaxImageSide) + "x" +
                std::to_string(kMaxImageSide) + " is read");
  }
}

}  // namespace

Image ReadPng(const std::string& path) {
  const std::vector<std::uint8_t> bytes = ReadFileBytes(path);
  CheckPngHeader(path, bytes);
  if (bytes.size() > INT_MAX) throw Error(path + ": PNG file over 2 GB");
  Image image;
  int channels_in_file = 0;
  // asking for 3 channels makes stb expand grey, drop alpha and reduce 16-bit samples
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()),
                                          &image.width, &image.height, &channels_in_file, 3);
  if (pixels == nullptr) {
    throw Error(path + ": cannot decode PNG: " + stbi_failure_reason());
  }
  image.rgb.assign(pixels, pixels + std::size_t(image.width) * image.height * 3);
  stbi_image_free(pixels);
  return image;
}

}  // namespace urdfsnap::image
