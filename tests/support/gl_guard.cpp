// urdfsnap_gl_guard: runs a command-line test only where it can render.
// usage: urdfsnap_gl_guard [--backend NAME]... [--] COMMAND [ARG...]
// Makes a GL context of each backend named (none named: the one the urdfsnap binary would use,
// URDFSNAP_GL_BACKEND else auto), then runs COMMAND in its place (exec). When one cannot be
// made it prints the factory's reason and exits 77, which CTest counts as skipped
// (SKIP_RETURN_CODE 77); under CI=true it exits 1 instead, so a broken CI machine is noticed.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "gl/backend.h"
#include "support/gl_probe.h"

int main(int argc, char** argv) {
  using namespace urdfsnap;
  std::vector<std::optional<gl::Backend>> backends;
  int i = 1;
  try {
    for (; i + 1 < argc && std::strcmp(argv[i], "--backend") == 0; i += 2) {
      backends.push_back(gl::ParseBackend(argv[i + 1]));
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "urdfsnap_gl_guard: %s\n", e.what());
    return 2;
  }
  if (i < argc && std::strcmp(argv[i], "--") == 0) ++i;
  if (i >= argc) {
    std::fprintf(stderr, "usage: urdfsnap_gl_guard [--backend NAME]... [--] COMMAND [ARG...]\n");
    return 2;
  }
  if (backends.empty()) backends.push_back(std::nullopt);
  for (const auto& backend : backends) {
    const std::string reason = test::NoGlReason(backend);
    if (reason.empty()) continue;
    if (test::InCi()) {
      std::printf("FAIL: %s (CI=true: a machine without GL fails rather than skips)\n", reason.c_str());
      return 1;
    }
    std::printf("skipped: %s\n", reason.c_str());
    return 77;
  }
  std::fflush(stdout);
  execvp(argv[i], argv + i);
  std::fprintf(stderr, "urdfsnap_gl_guard: cannot run %s: %s\n", argv[i], std::strerror(errno));
  return 2;
}
