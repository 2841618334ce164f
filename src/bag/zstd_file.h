// zstd as rosbag2's compression plugin writes it (rosbag2_compression_zstd): a whole split file
// compressed (compression_mode FILE: NAME_0.mcap.zstd), or each message's data (MESSAGE), read
// through Debian's libzstd with bounded output.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace urdfsnap::bag {

// The largest decompressed split file and message urdfsnap accepts: far above rosbag2's default
// split sizes and messages, and a bound on what a zstd bomb can make it write or allocate.
inline constexpr std::uint64_t kMaxDecompressedFileBytes = std::uint64_t{16} << 30;
inline constexpr std::uint64_t kMaxDecompressedMessageBytes = std::uint64_t{64} << 20;

// `file` decompressed into a temporary file (in TMPDIR, else /tmp), removed with this object.
// Throws urdfsnap::Error "FILE: ..." when it cannot be read, is not zstd, is truncated or
// decompresses to more than kMaxDecompressedFileBytes.
class ZstdFileCopy {
 public:
  explicit ZstdFileCopy(const std::string& file);
  ~ZstdFileCopy();
  ZstdFileCopy(const ZstdFileCopy&) = delete;
  ZstdFileCopy& operator=(const ZstdFileCopy&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// `data` decompressed into `buffer` (reused); returns the decompressed bytes. Throws
// std::runtime_error for data that is not zstd, is truncated, or decompresses to more than
// kMaxDecompressedMessageBytes.
std::span<const std::uint8_t> DecompressZstdMessage(std::span<const std::uint8_t> data,
                                                    std::vector<std::uint8_t>& buffer);

}  // namespace urdfsnap::bag
