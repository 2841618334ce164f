// The random numbers of one dataset sample: a SplitMix64 stream seeded from (seed, sample index),
// so sample k is the same whichever shard draws it and in whichever order, and the same on every
// platform (no std:: distributions, whose algorithms the standard leaves to the library).
#pragma once

#include <cstdint>

namespace urdfsnap::dataset {

class SampleRandom {
 public:
  SampleRandom(std::uint64_t seed, std::uint64_t sample);

  // The next 64 random bits.
  std::uint64_t Next();
  // A number uniform in [low, high) (low when they are equal).
  double Uniform(double low, double high);

 private:
  std::uint64_t state_;
};

}  // namespace urdfsnap::dataset
