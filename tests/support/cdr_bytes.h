// CDR bytes built field by field the way the specification lays them out (the 4-byte
// encapsulation header, then each primitive aligned to its size from after it), for tests that
// decode messages made by hand.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace urdfsnap::test {

class CdrBytes {
 public:
  explicit CdrBytes(bool big_endian = false) : big_endian_(big_endian) {
    bytes_ = {0x00, std::uint8_t(big_endian ? 0x00 : 0x01), 0x00, 0x00};
  }
  CdrBytes& U8(std::uint8_t value) { return Put(value); }
  CdrBytes& I32(std::int32_t value) { return Put(value); }
  CdrBytes& U32(std::uint32_t value) { return Put(value); }
  CdrBytes& F32(float value) { return Put(value); }
  CdrBytes& F64(double value) { return Put(value); }
  CdrBytes& Str(const std::string& text) {
    U32(static_cast<std::uint32_t>(text.size() + 1));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
    bytes_.push_back(0);
    return *this;
  }
  CdrBytes& Raw(std::vector<std::uint8_t> raw) {
    bytes_.insert(bytes_.end(), raw.begin(), raw.end());
    return *this;
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  template <typename T>
  CdrBytes& Put(T value) {
    while ((bytes_.size() - 4) % sizeof(T) != 0) bytes_.push_back(0xEE);  // padding
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (big_endian_) std::reverse(raw, raw + sizeof(T));
    bytes_.insert(bytes_.end(), raw, raw + sizeof(T));
    return *this;
  }
  bool big_endian_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace urdfsnap::test
