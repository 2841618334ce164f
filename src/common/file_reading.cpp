// Bounded whole-file reading with POSIX read(2): one loop for regular files, pipes and devices.
#include "common/file_reading.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace urdfsnap {
namespace {

[[noreturn]] void ThrowSystemError(int error_number) {
  throw FileReadError(std::system_category().message(error_number), error_number);
}

// Closes the descriptor when reading ends, however it ends.
struct Descriptor {
  int fd;
  ~Descriptor() { ::close(fd); }
};

}  // namespace

std::string ReadFileBounded(const std::string& path, std::size_t max_bytes) {
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) ThrowSystemError(errno);
  std::string bytes;
  // read one chunk past the limit, so that a file of exactly max_bytes is accepted
  constexpr std::size_t kChunk = 1 << 16;
  while (true) {
    const std::size_t old_size = bytes.size();
    if (old_size > max_bytes) {
      throw FileReadError("larger than the limit of " + std::to_string(max_bytes >> 20) + " MiB", 0);
    }
    bytes.resize(old_size + kChunk);
    const ssize_t n = ::read(file.fd, bytes.data() + old_size, kChunk);
    if (n < 0) {
      if (errno == EINTR) {
        bytes.resize(old_size);
        continue;
      }
      ThrowSystemError(errno);
    }
    bytes.resize(old_size + static_cast<std::size_t>(n));
    if (n == 0) return bytes;
  }
}

}  // namespace urdfsnap
