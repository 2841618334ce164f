// FileCursor on POSIX pread: one descriptor, a 256 KiB buffer refilled at the cursor.
#include "bag/internal/file_cursor.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "common/error.h"

namespace urdfsnap::bag {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{256} << 10;

[[noreturn]] void ThrowSystemError(const std::string& path, int error_number) {
  throw Error(path + ": cannot read: " + std::system_category().message(error_number));
}

}  // namespace

FileCursor::FileCursor(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) ThrowSystemError(path_, errno);
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const int error_number = errno;
    ::close(fd_);
    ThrowSystemError(path_, error_number);
  }
  if (!S_ISREG(status.st_mode)) {
    ::close(fd_);
    throw Error(path_ + ": cannot read: " +
                (S_ISDIR(status.st_mode) ? "it is a directory" : "not a regular file"));
  }
  size_ = static_cast<std::uint64_t>(status.st_size);
  buffer_ = std::make_unique_for_overwrite<std::uint8_t[]>(kBufferBytes);
}

FileCursor::~FileCursor() { ::close(fd_); }

void FileCursor::ReadDirect(std::uint64_t at, void* out, std::size_t size) {
  auto* bytes = static_cast<std::uint8_t*>(out);
  while (size > 0) {
    const ssize_t n = ::pread(fd_, bytes, size, static_cast<off_t>(at));
    if (n < 0) {
      if (errno == EINTR) continue;
      ThrowSystemError(path_, errno);
    }
    if (n == 0) throw Error(path_ + ": cannot read: the file became shorter while being read");
    bytes += n;
    at += static_cast<std::uint64_t>(n);
    size -= static_cast<std::size_t>(n);
  }
}

void FileCursor::ReadAt(std::uint64_t offset, void* out, std::size_t size) {
  ReadDirect(offset, out, size);
}

void FileCursor::Read(void* out, std::size_t size) {
  if (size == 0) return;  // `out` may be null then (found by fuzzing: memcpy(NULL, p, 0))
  auto* bytes = static_cast<std::uint8_t*>(out);
  // what the buffer already holds at the cursor
  if (offset_ >= buffer_start_ && offset_ < buffer_start_ + buffer_size_) {
    const std::size_t at = static_cast<std::size_t>(offset_ - buffer_start_);
    const std::size_t n = std::min(size, buffer_size_ - at);
    std::memcpy(bytes, buffer_.get() + at, n);
    bytes += n;
    size -= n;
    offset_ += n;
  }
  if (size == 0) return;
  if (size >= kBufferBytes) {
    ReadDirect(offset_, bytes, size);
    offset_ += size;
    return;
  }
  // refill at the cursor, as much as the file has
  buffer_start_ = offset_;
  buffer_size_ = static_cast<std::size_t>(std::min<std::uint64_t>(kBufferBytes, remaining()));
  if (buffer_size_ < size) {
    throw Error(path_ + ": cannot read: the file became shorter while being read");
  }
  ReadDirect(buffer_start_, buffer_.get(), buffer_size_);
  std::memcpy(bytes, buffer_.get(), size);
  offset_ += size;
}

void FileCursor::Skip(std::uint64_t size) { offset_ = std::min(size_, offset_ + size); }

}  // namespace urdfsnap::bag
