// CdrReader: alignment from the payload's origin (byte 4), byte swapping for big-endian data.
#include "bag/cdr_reader.h"

#include <bit>
#include <cstring>

namespace urdfsnap::bag {
namespace {

constexpr std::size_t kHeaderBytes = 4;

std::string RepresentationName(std::uint16_t id) {
  switch (id) {
    case 0x0002:
    case 0x0003:
      return "PL_CDR (a parameter list)";
    case 0x0006:
    case 0x0007:
      return "XCDR2";
    case 0x0008:
    case 0x0009:
      return "delimited XCDR2";
    case 0x000a:
    case 0x000b:
      return "PL_CDR2 (a parameter list)";
    default:
      return "unknown";
  }
}

template <typename T>
T ByteSwapped(T value) {
  if constexpr (sizeof(T) == 1) {
    return value;
  } else if constexpr (sizeof(T) == 2) {
    std::uint16_t bits;
    std::memcpy(&bits, &value, 2);
    bits = __builtin_bswap16(bits);
    std::memcpy(&value, &bits, 2);
  } else if constexpr (sizeof(T) == 4) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    bits = __builtin_bswap32(bits);
    std::memcpy(&value, &bits, 4);
  } else {
    std::uint64_t bits;
    std::memcpy(&bits, &value, 8);
    bits = __builtin_bswap64(bits);
    std::memcpy(&value, &bits, 8);
  }
  return value;
}

}  // namespace

CdrReader::CdrReader(std::span<const std::uint8_t> data) : data_(data) {
  if (data.size() < kHeaderBytes) {
    throw CdrError("a message of " + std::to_string(data.size()) +
                   " bytes, too short for CDR's encapsulation header");
  }
  // the representation identifier is big-endian whatever the data's byte order
  const std::uint16_t representation = static_cast<std::uint16_t>(data[0] << 8 | data[1]);
  if (representation > 0x0001) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%04x", representation);
    throw CdrError(
        "CDR representation " + std::string(hex) + " (" + RepresentationName(representation) +
        "), which urdfsnap does not read; ROS 2 messages are plain CDR (0x0000, 0x0001)");
  }
  big_endian_ = representation == 0x0000;
  offset_ = kHeaderBytes;
}

void CdrReader::Align(std::size_t size) {
  const std::size_t from_origin = offset_ - kHeaderBytes;
  offset_ += (size - from_origin % size) % size;
}

const std::uint8_t* CdrReader::Take(std::size_t size, const char* what) {
  if (offset_ > data_.size() || size > data_.size() - offset_) {
    throw CdrError(std::string(what) + " at byte " + std::to_string(offset_) +
                   " runs past the message's end (" + std::to_string(data_.size()) + " bytes)");
  }
  const std::uint8_t* bytes = data_.data() + offset_;
  offset_ += size;
  return bytes;
}

template <typename T>
T CdrReader::Primitive(const char* what) {
  Align(sizeof(T));
  T value;
  std::memcpy(&value, Take(sizeof(T), what), sizeof(T));
  return big_endian_ != (std::endian::native == std::endian::big) ? ByteSwapped(value) : value;
}

std::span<const std::uint8_t> CdrReader::Bytes(std::size_t count) {
  return {Take(count, "a byte array"), count};
}

std::int32_t CdrReader::Int32() { return Primitive<std::int32_t>("an int32"); }
std::uint32_t CdrReader::Uint32() { return Primitive<std::uint32_t>("a uint32"); }
double CdrReader::Float64() { return Primitive<double>("a float64"); }

std::string_view CdrReader::String() {
  const std::uint32_t length = Primitive<std::uint32_t>("a string's length");
  const std::size_t at = offset_;
  const auto* bytes = reinterpret_cast<const char*>(Take(length, "a string"));
  if (length == 0 || bytes[length - 1] != '\0') {
    throw CdrError("the string at byte " + std::to_string(at) + " has no terminating NUL");
  }
  return {bytes, length - 1};
}

float CdrReader::Float32() { return Primitive<float>("a float32"); }

std::uint64_t CdrReader::Unsigned(std::size_t bytes) {
  switch (bytes) {
    case 1: return Primitive<std::uint8_t>("a uint8");
    case 2: return Primitive<std::uint16_t>("a uint16");
    case 4: return Primitive<std::uint32_t>("a uint32");
    default: return Primitive<std::uint64_t>("a uint64");
  }
}

std::int64_t CdrReader::Signed(std::size_t bytes) {
  switch (bytes) {
    case 1: return Primitive<std::int8_t>("an int8");
    case 2: return Primitive<std::int16_t>("an int16");
    case 4: return Primitive<std::int32_t>("an int32");
    default: return Primitive<std::int64_t>("an int64");
  }
}

void CdrReader::SkipWideString() {
  const std::uint32_t count = Primitive<std::uint32_t>("a wstring's length");
  CheckFits(count, 4, "a wstring");
  Take(std::size_t{count} * 4, "a wstring");
}

void CdrReader::CheckFits(std::uint32_t count, std::size_t min_element_bytes,
                          const char* what) const {
  const std::size_t left = offset_ <= data_.size() ? data_.size() - offset_ : 0;
  if (min_element_bytes > 0 && count > left / min_element_bytes) {
    throw CdrError(std::string(what) + " of " + std::to_string(count) + " elements at byte " +
                   std::to_string(offset_) + ", more than the " + std::to_string(left) +
                   " bytes left can hold");
  }
}

std::uint32_t CdrReader::SequenceLength(std::size_t min_element_bytes) {
  const std::uint32_t count = Primitive<std::uint32_t>("a sequence's length");
  CheckFits(count, min_element_bytes, "a sequence");
  return count;
}

std::uint32_t CdrReader::FixedLength(std::uint32_t length, std::size_t min_element_bytes) {
  CheckFits(length, min_element_bytes, "a fixed array");
  return length;
}

}  // namespace urdfsnap::bag
