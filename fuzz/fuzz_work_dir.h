// For fuzz targets whose input names other files (xacro includes, mesh URIs): a fresh empty folder
// made the working folder, so relative names find nothing of the machine's and the input file
// written there is the target's own.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace urdfsnap::fuzz {

// Makes a new folder under /tmp the working folder, removed with its content when the process
// exits normally; call once, from LLVMFuzzerInitialize.
inline void EnterFreshWorkDir() {
  static char name[] = "/tmp/urdfsnap-fuzz-XXXXXX";
  if (!mkdtemp(name) || chdir(name) != 0) {
    std::perror("urdfsnap fuzz: cannot make a working folder");
    std::abort();
  }
  std::atexit([] { std::filesystem::remove_all(name); });
}

// Writes `size` bytes to `name` in the working folder (replacing it) and returns the name.
inline std::string WriteInput(const char* name, const uint8_t* data, size_t size) {
  std::FILE* file = std::fopen(name, "wb");
  if (!file || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) std::abort();
  return name;
}

}  // namespace urdfsnap::fuzz
