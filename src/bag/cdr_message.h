// Decoding any CDR message whose definition is known (bag/message_schema.h) into a tree of values,
// so that the messages urdfsnap reads (JointState, TFMessage, String) come out of one reader
// whether their definition came from the bag or shipped with urdfsnap.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bag/message_schema.h"

namespace urdfsnap::bag {

// One decoded value: a number (every integer, float and bool, as a double: exact for the 32-bit
// stamps and counts urdfsnap reads), a string, a list of values (an array's elements, or a
// message's fields in definition order, with `type` set), or the raw bytes of a uint8/byte/char
// array (a PointCloud2's or an image's data: one MessageValue per byte would take 100 times the
// memory), with `items` empty.
struct MessageValue {
  double number = 0;
  std::string text;
  std::vector<MessageValue> items;
  std::vector<std::uint8_t> bytes;
  const MessageType* type = nullptr;  // a message: its definition

  // The field `name` of a message. Throws CdrError when this is no message or has no such field
  // (a bag's definition that lacks a field urdfsnap reads).
  const MessageValue& operator[](std::string_view name) const;
};

// Decodes `cdr` (encapsulation header first) as the schema's root type. Throws CdrError for data
// that runs past its end, a string without its NUL, or a sequence longer than the bytes left.
MessageValue DecodeMessage(const MessageSchema& schema, std::span<const std::uint8_t> cdr);

}  // namespace urdfsnap::bag
