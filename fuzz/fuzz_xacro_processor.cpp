// Fuzz target: the xacro processor on one file (includes and load_yaml may name others). Any
// outcome but a result or urdfsnap::Error is a bug: a crash, a sanitizer report, another exception
// type (a message without the file), a hang or unbounded memory.
#include <cstddef>
#include <cstdint>

#include "common/error.h"
#include "fuzz_work_dir.h"
#include "xacro/xacro.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = urdfsnap::fuzz::WriteInput("robot.xacro", data, size);
  urdfsnap::xacro::Options options;
  options.args = {{"arg", "1.5"}};
  // the same limit code with a smaller budget, so that runaway inputs end in milliseconds
  options.max_document_bytes = std::size_t{8} << 20;
  urdfsnap::Warnings warnings;
  try {
    urdfsnap::xacro::ExpandFile(path, options, warnings);
  } catch (const urdfsnap::Error&) {
  }
  return 0;
}
