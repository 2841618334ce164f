// ZstdFileCopy and DecompressZstdMessage: ZSTD's streaming API, output counted against the limits
// as it is produced (a frame's declared size is not trusted).
#include "bag/zstd_file.h"

#include <unistd.h>
#include <zstd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "common/error.h"

namespace urdfsnap::bag {
namespace {

struct FreeContext {
  void operator()(ZSTD_DCtx* context) const { ZSTD_freeDCtx(context); }
};

// Streams `in` through zstd, passing each decompressed piece to `out`; throws std::runtime_error
// when the data is bad, ends inside a frame, or decompresses to more than `limit` bytes.
template <typename Read, typename Write>
void Decompress(Read&& read, Write&& write, std::uint64_t limit) {
  const std::unique_ptr<ZSTD_DCtx, FreeContext> context(ZSTD_createDCtx());
  if (!context) throw std::runtime_error("zstd: out of memory");
  std::vector<char> in_buffer(ZSTD_DStreamInSize()), out_buffer(ZSTD_DStreamOutSize());
  std::uint64_t total = 0;
  std::size_t last = 0;  // ZSTD's hint: 0 once a frame is complete
  bool any = false;
  for (std::size_t size; (size = read(in_buffer.data(), in_buffer.size())) > 0;) {
    any = true;
    ZSTD_inBuffer in{in_buffer.data(), size, 0};
    while (in.pos < in.size) {
      ZSTD_outBuffer out{out_buffer.data(), out_buffer.size(), 0};
      last = ZSTD_decompressStream(context.get(), &out, &in);
      if (ZSTD_isError(last)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(last));
      total += out.pos;
      if (total > limit) {
        throw std::runtime_error("zstd data decompresses to more than " +
                                 std::to_string(limit >> 20) + " MiB");
      }
      write(out_buffer.data(), out.pos);
    }
  }
  if (!any || last != 0) throw std::runtime_error("zstd data ends inside a frame");
}

}  // namespace

ZstdFileCopy::ZstdFileCopy(const std::string& file) {
  const char* folder = std::getenv("TMPDIR");
  std::string name = std::string(folder && *folder ? folder : "/tmp") + "/urdfsnap-bag-XXXXXX";
  const int descriptor = mkstemp(name.data());
  if (descriptor < 0) {
    throw Error(file + ": cannot make a temporary file to decompress it into: " +
                std::strerror(errno));
  }
  close(descriptor);
  path_ = name;
  std::ifstream in(file, std::ios::binary);
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  if (!in) {
    std::remove(path_.c_str());
    throw Error(file + ": cannot read it: " + std::strerror(errno));
  }
  try {
    Decompress(
        [&](char* data, std::size_t size) {
          in.read(data, static_cast<std::streamsize>(size));
          return static_cast<std::size_t>(in.gcount());
        },
        [&](const char* data, std::size_t size) {
          if (!out.write(data, static_cast<std::streamsize>(size))) {
            throw std::runtime_error("cannot write the temporary file " + path_);
          }
        },
        kMaxDecompressedFileBytes);
    out.close();
    if (!out) throw std::runtime_error("cannot write the temporary file " + path_);
  } catch (const std::runtime_error& e) {
    std::remove(path_.c_str());
    throw Error(file + ": compression_mode FILE: " + e.what());
  }
}

ZstdFileCopy::~ZstdFileCopy() { std::remove(path_.c_str()); }

std::span<const std::uint8_t> DecompressZstdMessage(std::span<const std::uint8_t> data,
                                                    std::vector<std::uint8_t>& buffer) {
  buffer.clear();
  std::size_t offset = 0;
  Decompress(
      [&](char* out, std::size_t size) {
        const std::size_t n = std::min(size, data.size() - offset);
        std::memcpy(out, data.data() + offset, n);
        offset += n;
        return n;
      },
      [&](const char* piece, std::size_t size) { buffer.insert(buffer.end(), piece, piece + size); },
      kMaxDecompressedMessageBytes);
  return buffer;
}

}  // namespace urdfsnap::bag
