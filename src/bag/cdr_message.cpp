// DecodeMessage: a walk over the schema's fields in order, each primitive read through CdrReader
// (aligned to its size), arrays as counted or fixed runs (uint8 ones copied as bytes), nested
// messages inline as CDR lays them.
#include "bag/cdr_message.h"

#include <algorithm>

#include "bag/cdr_reader.h"

namespace urdfsnap::bag {
namespace {

class Decoder {
 public:
  Decoder(const MessageSchema& schema, std::span<const std::uint8_t> cdr)
      : schema_(schema), reader_(cdr), min_type_bytes_(schema.types().size(), 0) {}

  MessageValue Message(int type) {
    MessageValue value;
    value.type = &schema_.types()[type];
    value.items.reserve(value.type->fields.size());
    for (const MessageField& field : value.type->fields) value.items.push_back(Field(field));
    return value;
  }

 private:
  MessageValue Field(const MessageField& field) {
    if (field.array == MessageField::Array::kNone) return Element(field);
    const std::size_t min_bytes = MinBytes(field);
    const std::uint32_t count = field.array == MessageField::Array::kFixed
                                    ? reader_.FixedLength(field.length, min_bytes)
                                    : reader_.SequenceLength(min_bytes);
    MessageValue list;
    if (field.kind == FieldKind::kUint8) {
      const std::span<const std::uint8_t> bytes = reader_.Bytes(count);
      list.bytes.assign(bytes.begin(), bytes.end());
      return list;
    }
    list.items.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) list.items.push_back(Element(field));
    return list;
  }

  MessageValue Element(const MessageField& field) {
    MessageValue value;
    switch (field.kind) {
      case FieldKind::kBool: case FieldKind::kUint8: value.number = reader_.Unsigned(1); break;
      case FieldKind::kInt8: value.number = static_cast<double>(reader_.Signed(1)); break;
      case FieldKind::kUint16: value.number = reader_.Unsigned(2); break;
      case FieldKind::kInt16: value.number = static_cast<double>(reader_.Signed(2)); break;
      case FieldKind::kUint32: value.number = reader_.Unsigned(4); break;
      case FieldKind::kInt32: value.number = static_cast<double>(reader_.Signed(4)); break;
      case FieldKind::kUint64: value.number = static_cast<double>(reader_.Unsigned(8)); break;
      case FieldKind::kInt64: value.number = static_cast<double>(reader_.Signed(8)); break;
      case FieldKind::kFloat32: value.number = reader_.Float32(); break;
      case FieldKind::kFloat64: value.number = reader_.Float64(); break;
      case FieldKind::kString: value.text = reader_.String(); break;
      case FieldKind::kWstring: reader_.SkipWideString(); break;  // urdfsnap reads none
      case FieldKind::kMessage: return Message(field.type);
    }
    return value;
  }

  // The fewest bytes one element of `field` takes: what a corrupt sequence length is checked
  // against before anything is allocated. Every type takes at least one byte (an empty message
  // holds rosidl's placeholder byte), so a message decodes to no more values than it has bytes.
  std::size_t MinBytes(const MessageField& field) {
    switch (field.kind) {
      case FieldKind::kBool: case FieldKind::kInt8: case FieldKind::kUint8: return 1;
      case FieldKind::kInt16: case FieldKind::kUint16: return 2;
      case FieldKind::kInt32: case FieldKind::kUint32: case FieldKind::kFloat32: return 4;
      case FieldKind::kInt64: case FieldKind::kUint64: case FieldKind::kFloat64: return 8;
      case FieldKind::kString: return 5;   // a length and the NUL
      case FieldKind::kWstring: return 4;  // a length
      case FieldKind::kMessage: return MinTypeBytes(field.type);
    }
    return 1;
  }

  // Worked out once per type (nesting is bounded by MessageSchema), saturating far above any
  // message's size.
  std::size_t MinTypeBytes(int type) {
    std::size_t& bytes = min_type_bytes_[type];
    if (bytes != 0) return bytes;
    constexpr std::size_t kCap = std::size_t{1} << 40;
    std::size_t sum = 0;
    for (const MessageField& field : schema_.types()[type].fields) {
      const std::size_t element = MinBytes(field);
      switch (field.array) {
        case MessageField::Array::kNone: sum += element; break;
        case MessageField::Array::kSequence: sum += 4; break;
        case MessageField::Array::kFixed:
          sum += field.length == 0 ? 0 : std::min(kCap / field.length, element) * field.length;
          break;
      }
      sum = std::min(sum, kCap);
    }
    bytes = std::max<std::size_t>(sum, 1);
    return bytes;
  }

  const MessageSchema& schema_;
  CdrReader reader_;
  std::vector<std::size_t> min_type_bytes_;  // per type, 0 until worked out
};

}  // namespace

const MessageValue& MessageValue::operator[](std::string_view name) const {
  const int index = type ? type->FieldIndex(name) : -1;
  if (index < 0) {
    throw CdrError(type ? "the definition of " + type->name + " has no field '" + std::string(name) + "'"
                        : "expected a message with a field '" + std::string(name) + "'");
  }
  return items[index];
}

MessageValue DecodeMessage(const MessageSchema& schema, std::span<const std::uint8_t> cdr) {
  return Decoder(schema, cdr).Message(0);
}

}  // namespace urdfsnap::bag
