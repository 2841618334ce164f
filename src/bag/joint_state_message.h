// sensor_msgs/msg/JointState as ROS 2 serialises it in CDR, decoded into the fields urdfsnap needs:
// header.stamp, name[] and position[] (velocity and effort follow in the message and are not read).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

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

// Decodes one CDR-encoded JointState into `out`, reusing its vectors' memory. Throws CdrError for
// malformed data; name and position lists of different non-zero lengths are the caller's to judge.
void DecodeJointState(std::span<const std::uint8_t> cdr, JointStateMessage& out);

}  // namespace urdfsnap::bag
