// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014).
#include "dataset/sample_random.h"

namespace urdfsnap::dataset {

namespace {

constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ull;

std::uint64_t Mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

SampleRandom::SampleRandom(std::uint64_t seed, std::uint64_t sample) : state_(Mix(seed) ^ Mix(sample * kGolden + 1)) {}

std::uint64_t SampleRandom::Next() {
  state_ += kGolden;
  return Mix(state_);
}

double SampleRandom::Uniform(double low, double high) {
  // the top 53 bits as a fraction in [0, 1)
  const double fraction = static_cast<double>(Next() >> 11) * 0x1.0p-53;
  return low + (high - low) * fraction;
}

}  // namespace urdfsnap::dataset
