// sensor_msgs/msg/JointState decoded through its definition (bag/cdr_message.h) into the fields
// urdfsnap needs: header.stamp, name[] and position[].
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bag/message_schema.h"

namespace urdfsnap::bag {

// The ROS 2 type name of the messages decoded here, as bags record it in their schemas.
inline constexpr const char* kJointStateType = "sensor_msgs/msg/JointState";

struct JointStateMessage {
  std::int32_t stamp_sec = 0;       // header.stamp.sec
  std::uint32_t stamp_nanosec = 0;  // header.stamp.nanosec
  std::vector<std::string> names;
  std::vector<double> positions;  // radians or metres; may be empty (a state without positions)

  // header.stamp in nanoseconds.
  std::int64_t StampNanoseconds() const {
    return std::int64_t{stamp_sec} * 1'000'000'000 + stamp_nanosec;
  }
};

// Decodes one CDR-encoded JointState, laid out as `schema` defines it, into `out`. Throws CdrError
// for malformed data or a definition without the fields read; name and position lists of
// different non-zero lengths are the caller's to judge.
void DecodeJointState(const MessageSchema& schema, std::span<const std::uint8_t> cdr,
                      JointStateMessage& out);

}  // namespace urdfsnap::bag
