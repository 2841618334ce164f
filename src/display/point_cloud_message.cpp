// PointCloud2 and LaserScan out of decoded message trees.
#include "display/point_cloud_message.h"

namespace urdfsnap::display {
namespace {

// std_msgs/Header's frame and builtin_interfaces/Time stamp in nanoseconds.
void ReadHeader(const bag::MessageValue& value, std::string& frame_id, std::int64_t& stamp_ns) {
  const bag::MessageValue& header = value["header"];
  frame_id = header["frame_id"].text;
  const bag::MessageValue& stamp = header["stamp"];
  stamp_ns = static_cast<std::int64_t>(stamp["sec"].number) * 1'000'000'000 +
             static_cast<std::int64_t>(stamp["nanosec"].number);
}

std::uint32_t Uint32(const bag::MessageValue& value) { return static_cast<std::uint32_t>(value.number); }

std::vector<float> Floats(const bag::MessageValue& list) {
  std::vector<float> out;
  out.reserve(list.items.size());
  for (const bag::MessageValue& item : list.items) out.push_back(static_cast<float>(item.number));
  return out;
}

}  // namespace

PointCloud2 DecodePointCloud2(const bag::MessageValue& value) {
  PointCloud2 cloud;
  ReadHeader(value, cloud.frame_id, cloud.stamp_ns);
  cloud.height = Uint32(value["height"]);
  cloud.width = Uint32(value["width"]);
  for (const bag::MessageValue& field : value["fields"].items) {
    cloud.fields.push_back({field["name"].text, Uint32(field["offset"]),
                            static_cast<std::uint8_t>(field["datatype"].number), Uint32(field["count"])});
  }
  cloud.is_bigendian = value["is_bigendian"].number != 0;
  cloud.point_step = Uint32(value["point_step"]);
  cloud.row_step = Uint32(value["row_step"]);
  const bag::MessageValue& data = value["data"];
  cloud.data = data.bytes;
  if (cloud.data.empty()) {   // a message file's YAML gives the bytes as numbers
    cloud.data.reserve(data.items.size());
    for (const bag::MessageValue& byte : data.items) cloud.data.push_back(static_cast<std::uint8_t>(byte.number));
  }
  cloud.is_dense = value["is_dense"].number != 0;
  return cloud;
}

LaserScan DecodeLaserScan(const bag::MessageValue& value) {
  LaserScan scan;
  ReadHeader(value, scan.frame_id, scan.stamp_ns);
  scan.angle_min = static_cast<float>(value["angle_min"].number);
  scan.angle_max = static_cast<float>(value["angle_max"].number);
  scan.angle_increment = static_cast<float>(value["angle_increment"].number);
  scan.time_increment = static_cast<float>(value["time_increment"].number);
  scan.range_min = static_cast<float>(value["range_min"].number);
  scan.range_max = static_cast<float>(value["range_max"].number);
  scan.ranges = Floats(value["ranges"]);
  scan.intensities = Floats(value["intensities"]);
  return scan;
}

}  // namespace urdfsnap::display
