// PointCloudReader: layout checks in 64-bit arithmetic (every claim is a uint32, so no product of
// two overflows), and typed reads through memcpy.
#include "display/point_cloud_reader.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>

namespace urdfsnap::display {
namespace {

template <typename T>
T Read(const std::uint8_t* bytes, bool swap) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, bytes, sizeof(T));
  if (swap) std::reverse(raw, raw + sizeof(T));
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return value;
}

}  // namespace

std::size_t DatatypeSize(std::uint8_t datatype) {
  // sensor_msgs/PointField: INT8 1, UINT8 2, INT16 3, UINT16 4, INT32 5, UINT32 6, FLOAT32 7, FLOAT64 8
  static constexpr std::size_t kSizes[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
  return datatype < std::size(kSizes) ? kSizes[datatype] : 0;
}

PointCloudReader::PointCloudReader(const PointCloud2& cloud)
    : cloud_(cloud), swap_(cloud.is_bigendian != (std::endian::native == std::endian::big)) {
  const std::uint64_t width = cloud.width, height = cloud.height, step = cloud.point_step;
  if (width == 0 || height == 0) return;
  const std::uint64_t row_bytes = width * step;
  if (height > 1 && cloud.row_step < row_bytes) {
    throw CloudError("row_step " + std::to_string(cloud.row_step) + " is less than width (" +
                     std::to_string(width) + ") times point_step (" + std::to_string(step) + ")");
  }
  // (height - 1) * row_step < 2^64, and row_bytes is added only once it fits in the data
  const std::uint64_t needed = row_bytes > cloud.data.size() ? row_bytes : (height - 1) * cloud.row_step + row_bytes;
  if (needed > cloud.data.size()) {
    throw CloudError("data holds " + std::to_string(cloud.data.size()) + " bytes, fewer than the " +
                     std::to_string(needed) + " that " +
                     std::to_string(width) + " x " + std::to_string(height) + " points of point_step " +
                     std::to_string(step) + " (row_step " + std::to_string(cloud.row_step) + ") need");
  }
  if (step == 0) throw CloudError("point_step is 0");
  count_ = static_cast<std::size_t>(width * height);
}

int PointCloudReader::Find(std::string_view name) const {
  for (std::size_t i = 0; i < cloud_.fields.size(); ++i) {
    if (cloud_.fields[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int PointCloudReader::Field(std::string_view name) const {
  const int index = Find(name);
  if (index < 0) throw CloudError("the cloud has no field '" + std::string(name) + "'");
  Check(index);
  return index;
}

void PointCloudReader::Check(int index) const {
  const PointField& field = cloud_.fields[index];
  const std::size_t size = DatatypeSize(field.datatype);
  if (size == 0) {
    throw CloudError("field '" + field.name + "' has an unknown datatype " + std::to_string(field.datatype));
  }
  if (std::uint64_t{field.offset} + size > cloud_.point_step) {
    throw CloudError("field '" + field.name + "' (" + std::to_string(size) + " bytes at offset " +
                     std::to_string(field.offset) + ") does not fit in point_step " +
                     std::to_string(cloud_.point_step));
  }
}

const std::uint8_t* PointCloudReader::At(int field, std::size_t i) const {
  const std::size_t row = i / cloud_.width, column = i % cloud_.width;
  return cloud_.data.data() + row * std::size_t{cloud_.row_step} + column * std::size_t{cloud_.point_step} +
         cloud_.fields[field].offset;
}

float PointCloudReader::Value(int field, std::size_t i) const {
  const std::uint8_t* p = At(field, i);
  switch (cloud_.fields[field].datatype) {
    case 1: return static_cast<float>(Read<std::int8_t>(p, false));
    case 2: return static_cast<float>(Read<std::uint8_t>(p, false));
    case 3: return static_cast<float>(Read<std::int16_t>(p, swap_));
    case 4: return static_cast<float>(Read<std::uint16_t>(p, swap_));
    case 5: return static_cast<float>(Read<std::int32_t>(p, swap_));
    case 6: return static_cast<float>(Read<std::uint32_t>(p, swap_));
    case 7: return Read<float>(p, swap_);
    default: return static_cast<float>(Read<double>(p, swap_));
  }
}

std::uint32_t PointCloudReader::Bits(int field, std::size_t i) const {
  return Read<std::uint32_t>(At(field, i), swap_);
}

}  // namespace urdfsnap::display
