// Fuzz target: .rviz files (YAML) read into the view and scene options. Only urdfsnap::Error may
// come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "request/rviz_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Warnings warnings;
  try {
    request::ParseRvizConfig(text, "config.rviz", request::RvizConfig{}, warnings);
  } catch (const Error&) {
  }
  return 0;
}
