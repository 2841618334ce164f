// Reading whole input files with a size limit, so that a huge file, /dev/zero or an endless pipe
// ends with an error instead of exhausting memory. Pipes and devices are read like files (a model
// can come from `<(xacro robot.xacro)`); only the number of bytes is bounded.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace urdfsnap {

// The largest model, xacro, YAML, joint or .rviz file urdfsnap reads: hundreds of times any real
// robot description, and small enough that parsing it stays within a few GB.
inline constexpr std::size_t kMaxTextFileBytes = std::size_t{64} << 20;

// Why a file could not be read, without the path (callers put it where their format wants it):
// the system's reason ("No such file or directory", "Is a directory") with its errno, or "larger
// than the limit of 64 MiB" with errno_value 0.
class FileReadError : public std::runtime_error {
 public:
  FileReadError(const std::string& reason, int errno_value)
      : std::runtime_error(reason), errno_value(errno_value) {}
  int errno_value;
};

// Returns the bytes of the file at `path`, at most `max_bytes` of them; throws FileReadError when
// the file cannot be opened or read, or holds more than `max_bytes`.
std::string ReadFileBounded(const std::string& path, std::size_t max_bytes = kMaxTextFileBytes);

}  // namespace urdfsnap
