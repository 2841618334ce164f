// The messages of RViz's PointCloud2 and LaserScan displays as typed values (sensor_msgs/PointCloud2
// with its PointFields, sensor_msgs/LaserScan of ROS 2), decoded from a bag::MessageValue by field
// name so that the bag's own definition decides the layout. The cloud's data stays raw bytes
// (bag::MessageValue::bytes); display/point_cloud_reader.h reads points out of it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bag/cdr_message.h"

namespace urdfsnap::display {

// sensor_msgs/PointField: one named value of each point, `count` elements of `datatype` (INT8 = 1,
// UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 = 8) at `offset` bytes into the point.
struct PointField {
  std::string name;
  std::uint32_t offset = 0;
  std::uint8_t datatype = 0;
  std::uint32_t count = 1;
};

// sensor_msgs/PointCloud2: height rows of width points, each point_step bytes, rows row_step
// bytes apart, in the header's frame.
struct PointCloud2 {
  std::string frame_id;
  std::int64_t stamp_ns = 0;
  std::uint32_t height = 0;
  std::uint32_t width = 0;
  std::vector<PointField> fields;
  bool is_bigendian = false;
  std::uint32_t point_step = 0;
  std::uint32_t row_step = 0;
  std::vector<std::uint8_t> data;
  bool is_dense = false;
};

// sensor_msgs/LaserScan: ranges[i] measured at angle_min + i * angle_increment in the header's
// frame (its x axis at angle 0, z up).
struct LaserScan {
  std::string frame_id;
  std::int64_t stamp_ns = 0;
  float angle_min = 0;
  float angle_max = 0;
  float angle_increment = 0;
  float time_increment = 0;
  float range_min = 0;
  float range_max = 0;
  std::vector<float> ranges;
  std::vector<float> intensities;
};

// Decoders of a decoded message of that type. Throw bag::CdrError when a field they read is missing
// from the message's definition.
PointCloud2 DecodePointCloud2(const bag::MessageValue& value);
LaserScan DecodeLaserScan(const bag::MessageValue& value);

}  // namespace urdfsnap::display
