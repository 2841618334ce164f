// RandomSuffix: six characters from a 36-letter alphabet.
#include "common/random_suffix.h"

#include <random>

namespace urdfsnap {

std::string RandomSuffix() {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device device;
  std::uniform_int_distribution<int> pick(0, sizeof kAlphabet - 2);
  std::string suffix;
  for (int i = 0; i < 6; ++i) suffix += kAlphabet[pick(device)];
  return suffix;
}

}  // namespace urdfsnap
