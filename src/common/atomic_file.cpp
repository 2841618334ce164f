// Temporary-file-and-rename writing of whole files (PNG, and the HTML/XML/URDF other commands
// write) and of streams (AtomicFile: videos, written by urdfsnap or by libavformat).
#include "common/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "common/error.h"
#include "common/random_suffix.h"

namespace urdfsnap {
namespace {

[[noreturn]] void ThrowWriteError(const std::string& path, int error_number) {
  throw Error(path + ": cannot write: " + std::system_category().message(error_number));
}

// Opens a new temporary file beside `path` (not with mkstemp, which makes files mode 0600: an
// output image should get the usual 0666 less the umask); returns its descriptor and fills
// `temp_path`.
int CreateTemporary(const std::string& path, std::string& temp_path) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp_path = path + ".tmp-" + RandomSuffix();
    const int fd = ::open(temp_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) ThrowWriteError(path, errno);
  }
  ThrowWriteError(path, EEXIST);
}

// Writes all of `bytes` at the file position, or at `offset` when it is given; returns 0 or the
// errno of the failure.
int WriteAll(int fd, std::string_view bytes, std::int64_t offset = -1) {
  while (!bytes.empty()) {
    const ssize_t written = offset < 0 ? ::write(fd, bytes.data(), bytes.size())
                                       : ::pwrite(fd, bytes.data(), bytes.size(), offset);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
    if (offset >= 0) offset += written;
  }
  return 0;
}

}  // namespace

void RemoveFilesNamedWith(const std::string& folder, const std::string& part) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, error)) {
    if (entry.path().filename().string().find(part) != std::string::npos) std::filesystem::remove(entry.path(), error);
  }
}

void WriteFileAtomically(const std::string& path, std::string_view bytes) {
  AtomicFile file(path);
  file.Write(bytes);
  file.Commit();
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  fd_ = CreateTemporary(path_, temp_path_);
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (fd_ >= 0) ::close(fd_);
  ::unlink(temp_path_.c_str());
}

void AtomicFile::Write(std::string_view bytes) {
  if (const int error_number = WriteAll(fd_, bytes); error_number != 0) {
    ThrowWriteError(path_, error_number);
  }
}

void AtomicFile::WriteAt(std::uint64_t offset, std::string_view bytes) {
  if (const int error_number = WriteAll(fd_, bytes, static_cast<std::int64_t>(offset));
      error_number != 0) {
    ThrowWriteError(path_, error_number);
  }
}

void AtomicFile::Close() {
  if (fd_ < 0) return;
  const int error_number = ::close(fd_) != 0 ? errno : 0;
  fd_ = -1;
  if (error_number != 0) ThrowWriteError(path_, error_number);  // the destructor unlinks
}

void AtomicFile::Commit() {
  // no fsync: the promise is "never a partial file after a failed run", not durability across a
  // power cut, and fsync would cost more than encoding an image
  Close();
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) ThrowWriteError(path_, errno);  // the destructor unlinks
  committed_ = true;
}

}  // namespace urdfsnap
