// Reading CDR, the serialisation of ROS 2 messages (OMG CDR, XCDR version 1, as every ROS 2 rmw
// writes it and rosbag2 stores it): a 4-byte encapsulation header (representation 0x0000 big-endian
// or 0x0001 little-endian, then two option bytes), then each primitive aligned to its own size
// counted from the first byte after the header. Every read is checked against the end.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace urdfsnap::bag {

// Malformed CDR; what() says what was expected where ("string at byte 20 runs past the end").
class CdrError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CdrReader {
 public:
  // Reads the encapsulation header. Throws CdrError for a short buffer or a representation other
  // than plain CDR (XCDR2 and parameter lists are named in the message).
  explicit CdrReader(std::span<const std::uint8_t> data);

  std::int32_t Int32();
  std::uint32_t Uint32();
  double Float64();
  float Float32();
  // An unsigned or signed integer of 1, 2, 4 or 8 bytes.
  std::uint64_t Unsigned(std::size_t bytes);
  std::int64_t Signed(std::size_t bytes);
  // `count` raw bytes (a uint8[] or byte[] array's elements, which need no alignment).
  std::span<const std::uint8_t> Bytes(std::size_t count);
  // A wstring (uint32 count of 4-byte characters), skipped.
  void SkipWideString();
  // A string: uint32 length counting its terminating NUL, the bytes, the NUL (not returned).
  std::string_view String();
  // A sequence's element count, checked against the bytes left when each element takes at least
  // `min_element_bytes` (so that a corrupt count cannot make the caller allocate gigabytes).
  std::uint32_t SequenceLength(std::size_t min_element_bytes);
  // A fixed array's `length` (no count in the data), checked as SequenceLength checks a count.
  std::uint32_t FixedLength(std::uint32_t length, std::size_t min_element_bytes);

  bool big_endian() const { return big_endian_; }

 private:
  void Align(std::size_t size);
  void CheckFits(std::uint32_t count, std::size_t min_element_bytes, const char* what) const;
  const std::uint8_t* Take(std::size_t size, const char* what);
  template <typename T>
  T Primitive(const char* what);

  std::span<const std::uint8_t> data_;
  std::size_t offset_ = 0;  // from the start of data_, header included
  bool big_endian_ = false;
};

}  // namespace urdfsnap::bag
