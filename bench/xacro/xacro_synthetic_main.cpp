// `xacro_synthetic N`: prints a synthetic xacro document with N macro calls (for timing other
// xacro implementations on the same input).
#include <cstdio>
#include <cstdlib>

#include "synthetic_xacro.h"

int main(int argc, char** argv) {
  if (argc != 2 || std::atoi(argv[1]) < 0) {
    std::fprintf(stderr, "usage: xacro_synthetic N\n");
    return 2;
  }
  const std::string text = urdfsnap::bench::SyntheticXacro(std::atoi(argv[1]));
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}
