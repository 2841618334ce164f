// EncodeNpyFloat32: the magic "\x93NUMPY", version 1.0, a little-endian header length, a Python
// dict literal describing the array padded with spaces to a 64-byte boundary, then the raw data.
#include "image/npy_writer.h"

#include <bit>
#include <cstdint>
#include <cstring>

#include "common/atomic_file.h"
#include "common/error.h"

namespace urdfsnap::image {

static_assert(std::endian::native == std::endian::little, "the data are written as '<f4'");

std::string EncodeNpyFloat32(int width, int height, const std::vector<float>& values) {
  if (width <= 0 || height <= 0 ||
      values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw Error("EncodeNpyFloat32: " + std::to_string(values.size()) + " values do not make a " +
                std::to_string(width) + "x" + std::to_string(height) + " image");
  }
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(height) +
                       ", " + std::to_string(width) + "), }";
  const std::size_t preamble = 10;   // magic (6), version (2), header length (2)
  header.append(64 - (preamble + header.size() + 1) % 64, ' ');
  header += '\n';
  std::string bytes = "\x93NUMPY";
  bytes += '\x01';
  bytes += '\x00';
  bytes += static_cast<char>(header.size() & 0xFF);
  bytes += static_cast<char>(header.size() >> 8);
  bytes += header;
  const std::size_t data = bytes.size();
  bytes.resize(data + values.size() * sizeof(float));
  std::memcpy(bytes.data() + data, values.data(), values.size() * sizeof(float));
  return bytes;
}

void WriteNpyFloat32(int width, int height, const std::vector<float>& values, const std::string& path) {
  WriteFileAtomically(path, EncodeNpyFloat32(width, height, values));
}

}  // namespace urdfsnap::image
