// Sequential reading of a large binary file (a bag) through a small buffer: small reads are served
// from the buffer, large ones go straight into the caller's memory, skips seek. The file's size is
// known up front, so a record that claims more bytes than are left is caught before it is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace urdfsnap::bag {

class FileCursor {
 public:
  // Opens `path` for reading. Throws urdfsnap::Error "path: cannot read: <reason>" when it cannot
  // be opened or is not a regular file.
  explicit FileCursor(std::string path);
  ~FileCursor();

  FileCursor(const FileCursor&) = delete;
  FileCursor& operator=(const FileCursor&) = delete;

  // Copies the next `size` bytes into `out` and moves past them. Throws urdfsnap::Error when the
  // file ends sooner (it shrank while being read) or cannot be read.
  void Read(void* out, std::size_t size);
  // Moves past the next `size` bytes without reading them (size <= remaining()).
  void Skip(std::uint64_t size);
  // Reads `size` bytes at `offset` without moving the cursor.
  void ReadAt(std::uint64_t offset, void* out, std::size_t size);

  std::uint64_t offset() const { return offset_; }
  std::uint64_t size() const { return size_; }
  std::uint64_t remaining() const { return size_ - offset_; }
  const std::string& path() const { return path_; }

 private:
  void ReadDirect(std::uint64_t at, void* out, std::size_t size);

  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::uint64_t offset_ = 0;  // of the next byte handed out
  std::unique_ptr<std::uint8_t[]> buffer_;
  std::uint64_t buffer_start_ = 0;  // file offset of buffer_[0]
  std::size_t buffer_size_ = 0;     // valid bytes in buffer_
};

}  // namespace urdfsnap::bag
