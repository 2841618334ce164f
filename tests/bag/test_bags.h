// Where the test bags are: written into the build folder by scripts/make-test-bags.sh (the ctest
// fixture test_bags) with the MCAP project's own writer, and what their messages hold.
#pragma once

#include <cstdint>
#include <string>

namespace urdfsnap::test {

inline std::string TestBag(const std::string& name) {
  return std::string(URDFSNAP_BINARY_DIR) + "/test-bags/" + name;
}

// tests/node/make_test_bags.mjs: message i has header.stamp 1700000000 s + i * 10 ms, log time
// 1 ms later, and shoulder = 0.01 i, elbow = -0.02 i, wrist = 0.5.
inline constexpr std::int64_t kBagStartNanoseconds = 1'700'000'000LL * 1'000'000'000;
inline std::int64_t BagStamp(int i) { return kBagStartNanoseconds + i * 10'000'000LL; }
inline double BagShoulder(int i) { return 0.01 * i; }
inline double BagElbow(int i) { return -0.02 * i; }
inline constexpr double kBagWrist = 0.5;

}  // namespace urdfsnap::test
