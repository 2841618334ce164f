// ChunkDecompressor: one-shot zstd into the caller's buffer (no window allocation beyond it) and a
// streaming LZ4F loop that must fill the buffer exactly; contexts are reused from chunk to chunk.
#include "bag/internal/chunk_decompressor.h"

#include <lz4frame.h>
#include <zstd.h>
#include <zstd_errors.h>

#include <stdexcept>
#include <string>

namespace urdfsnap::bag {

struct ChunkDecompressor::Contexts {
  ZSTD_DCtx* zstd = nullptr;
  LZ4F_dctx* lz4 = nullptr;
  ~Contexts() {
    ZSTD_freeDCtx(zstd);
    LZ4F_freeDecompressionContext(lz4);
  }
};

namespace {

std::string Declared(std::size_t size) { return "the declared " + std::to_string(size) + " bytes"; }

void DecompressZstd(ZSTD_DCtx* context, std::span<const std::uint8_t> in,
                    std::span<std::uint8_t> out) {
  const std::size_t result =
      ZSTD_decompressDCtx(context, out.data(), out.size(), in.data(), in.size());
  if (ZSTD_isError(result)) {
    if (ZSTD_getErrorCode(result) == ZSTD_error_dstSize_tooSmall) {
      throw std::runtime_error("zstd data decompresses to more than " + Declared(out.size()));
    }
    throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(result));
  }
  if (result != out.size()) {
    throw std::runtime_error("zstd data decompresses to " + std::to_string(result) +
                             " bytes instead of " + Declared(out.size()));
  }
}

void DecompressLz4(LZ4F_dctx* context, std::span<const std::uint8_t> in,
                   std::span<std::uint8_t> out) {
  LZ4F_resetDecompressionContext(context);
  std::size_t in_at = 0, out_at = 0;
  std::size_t hint = out.empty() ? 0 : 1;  // nothing in, nothing out is no error
  // one or more frames, one after the other, until the input is used up
  while (in_at < in.size()) {
    std::size_t in_size = in.size() - in_at;
    std::size_t out_size = out.size() - out_at;
    hint = LZ4F_decompress(context, out.data() + out_at, &out_size, in.data() + in_at, &in_size,
                           nullptr);
    if (LZ4F_isError(hint))
      throw std::runtime_error(std::string("lz4: ") + LZ4F_getErrorName(hint));
    in_at += in_size;
    out_at += out_size;
    // no progress with input left: the output is full
    if (in_size == 0 && out_size == 0) {
      throw std::runtime_error("lz4 data decompresses to more than " + Declared(out.size()));
    }
  }
  if (hint != 0) throw std::runtime_error("lz4 data ends in the middle of a frame");
  if (out_at != out.size()) {
    throw std::runtime_error("lz4 data decompresses to " + std::to_string(out_at) +
                             " bytes instead of " + Declared(out.size()));
  }
}

}  // namespace

ChunkDecompressor::ChunkDecompressor() = default;
ChunkDecompressor::~ChunkDecompressor() = default;

bool ChunkDecompressor::Reads(std::string_view compression) {
  return compression == "zstd" || compression == "lz4";
}

void ChunkDecompressor::Decompress(std::string_view compression, std::span<const std::uint8_t> in,
                                   std::span<std::uint8_t> out) {
  if (!contexts_) contexts_ = std::make_unique<Contexts>();
  if (compression == "zstd") {
    if (!contexts_->zstd && !(contexts_->zstd = ZSTD_createDCtx())) throw std::bad_alloc();
    DecompressZstd(contexts_->zstd, in, out);
  } else if (compression == "lz4") {
    if (!contexts_->lz4 &&
        LZ4F_isError(LZ4F_createDecompressionContext(&contexts_->lz4, LZ4F_VERSION))) {
      throw std::bad_alloc();
    }
    DecompressLz4(contexts_->lz4, in, out);
  } else {
    throw std::runtime_error("unknown compression '" + std::string(compression) + "'");
  }
}

}  // namespace urdfsnap::bag
