// Bounded whole-file reading with POSIX read(2): one loop for regular files, pipes and devices.
#include "common/file_reading.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

namespace urdfsnap {
namespace {

[[noreturn]] void ThrowSystemError(int error_number) {
  throw FileReadError(std::system_category().message(error_number), error_number);
}

[[noreturn]] void ThrowTooLarge(std::size_t max_bytes) {
  throw FileReadError("larger than the limit of " + std::to_string(max_bytes >> 20) + " MiB", 0);
}

// Closes the descriptor when reading ends, however it ends.
struct Descriptor {
  int fd;
  ~Descriptor() { ::close(fd); }
};

// Standard input's names are read from this process's descriptor 0 itself: opening the name again
// opens a pipe anew, which waits for a writer forever when the one feeding it has already finished
// (`cat states.yaml | urdfsnap animate --trajectory /dev/stdin`).
int OpenForReading(const std::string& path) {
  if (path == "/dev/stdin" || path == "/dev/fd/0" || path == "/proc/self/fd/0") {
    return ::fcntl(STDIN_FILENO, F_DUPFD_CLOEXEC, 0);
  }
  return ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
}

}  // namespace

std::string ReadFileBounded(const std::string& path, std::size_t max_bytes) {
  const Descriptor file{OpenForReading(path)};
  if (file.fd < 0) ThrowSystemError(errno);
  // a regular file says how large it is: refuse it unread, or read it in one go (one byte more,
  // to see the end); anything else grows in chunks
  struct stat status {};
  const bool sized = ::fstat(file.fd, &status) == 0 && S_ISREG(status.st_mode);
  if (sized && static_cast<std::size_t>(status.st_size) > max_bytes) ThrowTooLarge(max_bytes);
  std::size_t chunk = sized ? static_cast<std::size_t>(status.st_size) + 1 : 4096;
  std::string bytes;
  while (true) {
    const std::size_t old_size = bytes.size();
    if (old_size > max_bytes) ThrowTooLarge(max_bytes);
    bytes.resize(old_size + chunk);
    const ssize_t n = ::read(file.fd, bytes.data() + old_size, chunk);
    if (n < 0 && errno != EINTR) ThrowSystemError(errno);
    bytes.resize(old_size + static_cast<std::size_t>(std::max<ssize_t>(n, 0)));
    if (n == 0) return bytes;
    chunk = std::clamp<std::size_t>(bytes.size(), 4096, std::size_t{1} << 20);
  }
}

}  // namespace urdfsnap
