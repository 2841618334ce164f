// The one place warnings reach the user.
#include <cstdio>

#include "cli/command.h"

namespace urdfsnap::cli {

void PrintWarnings(const Warnings& warnings) {
  for (const auto& message : warnings.messages()) {
    std::fprintf(stderr, "urdfsnap: warning: %s\n", message.c_str());
  }
}

}  // namespace urdfsnap::cli
