// Decompression of MCAP chunk records with Debian's libzstd and liblz4 (LZ4's frame format, as
// MCAP writers use it), into a buffer of exactly the size the chunk declares: data that would
// decompress to more or to less is an error, so the declared size bounds the memory.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

namespace urdfsnap::bag {

class ChunkDecompressor {
 public:
  ChunkDecompressor();
  ~ChunkDecompressor();

  ChunkDecompressor(const ChunkDecompressor&) = delete;
  ChunkDecompressor& operator=(const ChunkDecompressor&) = delete;

  // Whether `compression` (a chunk's compression field) names a format this class reads: "zstd"
  // or "lz4" ("" is no compression and needs no decompressor).
  static bool Reads(std::string_view compression);

  // Decompresses `in` into all of `out`. Throws std::runtime_error saying what is wrong ("zstd:
  // Data corruption detected", "lz4 data decompresses to more than the declared 4096 bytes").
  void Decompress(std::string_view compression, std::span<const std::uint8_t> in,
                  std::span<std::uint8_t> out);

 private:
  struct Contexts;
  std::unique_ptr<Contexts> contexts_;  // made on first use, kept for the next chunk
};

}  // namespace urdfsnap::bag
