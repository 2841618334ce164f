// Reading MCAP's little-endian fields (integers, uint32-length-prefixed strings, bytes) from a byte
// span with every read checked against the span's end, so that a record claiming more than it
// holds is a clear error naming the field rather than a read past the buffer.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace urdfsnap::bag {

// A field that does not fit in what is left of its record; what() names the field.
class TruncatedField : public std::runtime_error {
 public:
  explicit TruncatedField(const std::string& field)
      : std::runtime_error("field '" + field + "' runs past the end of the record") {}
};

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  std::uint8_t U8(const char* field) { return Fixed<std::uint8_t>(field); }
  std::uint16_t U16(const char* field) { return Fixed<std::uint16_t>(field); }
  std::uint32_t U32(const char* field) { return Fixed<std::uint32_t>(field); }
  std::uint64_t U64(const char* field) { return Fixed<std::uint64_t>(field); }

  // `size` bytes as a view into the span.
  std::span<const std::uint8_t> Bytes(std::uint64_t size, const char* field) {
    if (size > remaining()) throw TruncatedField(field);
    const auto view = bytes_.subspan(offset_, static_cast<std::size_t>(size));
    offset_ += static_cast<std::size_t>(size);
    return view;
  }

  // A uint32 byte length, then that many bytes of text.
  std::string_view String(const char* field) {
    const auto bytes = Bytes(U32(field), field);
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
  }

  void Skip(std::uint64_t size, const char* field) { Bytes(size, field); }

  std::size_t remaining() const { return bytes_.size() - offset_; }
  std::size_t offset() const { return offset_; }

 private:
  // MCAP is little-endian, as is every machine urdfsnap builds for (x86-64, arm64)
  template <typename T>
  T Fixed(const char* field) {
    static_assert(std::endian::native == std::endian::little);
    T value;
    std::memcpy(&value, Bytes(sizeof(T), field).data(), sizeof(T));
    return value;
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t offset_ = 0;
};

}  // namespace urdfsnap::bag
