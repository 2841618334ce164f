// DecodeJointState: the fields of std_msgs/Header and sensor_msgs/JointState in declaration order.
#include "bag/joint_state_message.h"

#include "bag/cdr_reader.h"

namespace urdfsnap::bag {

void DecodeJointState(std::span<const std::uint8_t> cdr, JointStateMessage& out) {
  CdrReader reader(cdr);
  // std_msgs/Header: builtin_interfaces/Time stamp {int32 sec, uint32 nanosec}, string frame_id
  out.stamp_sec = reader.Int32();
  out.stamp_nanosec = reader.Uint32();
  reader.String();
  // string[] name: each at least a length and a NUL
  const std::uint32_t name_count = reader.SequenceLength(4 + 1);
  out.names.resize(name_count);
  for (std::string& name : out.names) name = reader.String();
  // float64[] position
  const std::uint32_t position_count = reader.SequenceLength(8);
  out.positions.resize(position_count);
  for (double& position : out.positions) position = reader.Float64();
}

}  // namespace urdfsnap::bag
