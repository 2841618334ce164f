// DecodeJointState: the message decoded by its definition, then header.stamp, name and position
// taken by field name.
#include "bag/joint_state_message.h"

#include "bag/cdr_message.h"

namespace urdfsnap::bag {

void DecodeJointState(const MessageSchema& schema, std::span<const std::uint8_t> cdr,
                      JointStateMessage& out) {
  const MessageValue message = DecodeMessage(schema, cdr);
  const MessageValue& stamp = message["header"]["stamp"];
  out.stamp_sec = static_cast<std::int32_t>(stamp["sec"].number);
  out.stamp_nanosec = static_cast<std::uint32_t>(stamp["nanosec"].number);
  const MessageValue& names = message["name"];
  out.names.resize(names.items.size());
  for (std::size_t i = 0; i < names.items.size(); ++i) out.names[i] = names.items[i].text;
  const MessageValue& positions = message["position"];
  out.positions.resize(positions.items.size());
  for (std::size_t i = 0; i < positions.items.size(); ++i) {
    out.positions[i] = positions.items[i].number;
  }
}

}  // namespace urdfsnap::bag
