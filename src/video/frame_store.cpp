// FrameStore: zstd at a fast level (robot renders shrink ten- to thirtyfold: large flat background,
// smooth shading), each frame as a 4-byte size and its compressed bytes, pread/pwrite on the
// unnamed file.
#include "video/internal/frame_store.h"

#include <fcntl.h>
#include <unistd.h>
#include <zstd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "common/error.h"

namespace urdfsnap::video {
namespace {

// zstd's level 1: about 300 MB/s here, a third of the time of one GIF frame's dithering
constexpr int kCompressionLevel = 1;

std::string TemporaryFolder() {
  std::error_code error;
  const std::filesystem::path folder = std::filesystem::temp_directory_path(error);
  return error ? "/tmp" : folder.string();
}

// An unnamed temporary file, or a named one removed at once where O_TMPFILE is not supported.
int OpenUnnamedFile(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)) return fd;
  std::string name = folder + "/urdfsnap-frames-XXXXXX";
  const int named = ::mkostemp(name.data(), O_CLOEXEC);
  if (named >= 0) ::unlink(name.c_str());
  return named;
}

}  // namespace

FrameStore::FrameStore(int width, int height, std::string output)
    : width_(width), height_(height), output_(std::move(output)) {
  const std::string folder = TemporaryFolder();
  fd_ = OpenUnnamedFile(folder);
  if (fd_ < 0) {
    throw Error(output_ + ": cannot make a temporary file for the frames in " + folder + ": " +
                std::system_category().message(errno));
  }
  compressor_ = ZSTD_createCCtx();
  decompressor_ = ZSTD_createDCtx();
  if (!compressor_ || !decompressor_) throw std::bad_alloc();
  ZSTD_CCtx_setParameter(static_cast<ZSTD_CCtx*>(compressor_), ZSTD_c_compressionLevel,
                         kCompressionLevel);
}

FrameStore::~FrameStore() {
  ZSTD_freeCCtx(static_cast<ZSTD_CCtx*>(compressor_));
  ZSTD_freeDCtx(static_cast<ZSTD_DCtx*>(decompressor_));
  if (fd_ >= 0) ::close(fd_);
}

void FrameStore::Append(const image::Image& frame) {
  const std::size_t size = frame.rgb.size();
  compressed_.resize(4 + ZSTD_compressBound(size));
  const std::size_t written =
      ZSTD_compress2(static_cast<ZSTD_CCtx*>(compressor_), compressed_.data() + 4,
                     compressed_.size() - 4, frame.rgb.data(), size);
  if (ZSTD_isError(written)) {
    throw Error(output_ + ": cannot compress a frame: " + ZSTD_getErrorName(written));
  }
  const std::uint32_t length = static_cast<std::uint32_t>(written);
  std::memcpy(compressed_.data(), &length, 4);
  std::size_t done = 0;
  while (done < 4 + written) {
    const ssize_t n = ::pwrite(fd_, compressed_.data() + done, 4 + written - done,
                               static_cast<off_t>(stored_bytes_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw Error(output_ + ": cannot keep the frames in a temporary file: " +
                  std::system_category().message(n < 0 ? errno : ENOSPC));
    }
    done += static_cast<std::size_t>(n);
  }
  stored_bytes_ += done;
  ++count_;
}

void FrameStore::Rewind() { read_offset_ = 0; }

bool FrameStore::Next(image::Image& frame) {
  if (read_offset_ >= stored_bytes_) return false;
  const auto read = [&](void* out, std::size_t size) {
    if (::pread(fd_, out, size, static_cast<off_t>(read_offset_)) != static_cast<ssize_t>(size)) {
      throw Error(output_ + ": cannot read the frames back from their temporary file: " +
                  std::system_category().message(errno));
    }
    read_offset_ += size;
  };
  std::uint32_t length = 0;
  read(&length, 4);
  compressed_.resize(length);
  read(compressed_.data(), length);
  frame.width = width_;
  frame.height = height_;
  frame.rgb.resize(std::size_t(width_) * height_ * 3);
  const std::size_t size =
      ZSTD_decompressDCtx(static_cast<ZSTD_DCtx*>(decompressor_), frame.rgb.data(),
                          frame.rgb.size(), compressed_.data(), length);
  if (ZSTD_isError(size) || size != frame.rgb.size()) {
    throw Error(output_ + ": a frame in the temporary file does not decompress");
  }
  return true;
}

}  // namespace urdfsnap::video
