// Reading speed of a large bag: 20 s of JointStates at 1 kHz beside 30 Hz 640x480 camera images in
// zstd chunks of 4 MiB (553 MB of messages in a file of about 350 MB), written by the MCAP
// project's writer (scripts/make-test-bags.sh DIR --large). Reports MB/s of file and messages/s for
// the JointState topic alone (bag::ReadJointStates: decompress, skip the images, decode CDR) and
// for the whole trajectory (motion::ReadTrajectory), and the peak memory, which stays that of one
// chunk. usage: urdfsnap_mcap_bench [BAG]   (default: build/bench-bags/large_zstd.mcap, made if
// missing)
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bag/joint_state_bag.h"
#include "common/error.h"
#include "motion/trajectory_file.h"

namespace {

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double PeakMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace urdfsnap;
  std::string bag = argc > 1 ? argv[1] : URDFSNAP_BINARY_DIR "/bench-bags/large_zstd.mcap";
  if (argc == 1 && !std::filesystem::exists(bag)) {
    const std::string make =
        URDFSNAP_SOURCE_DIR "/scripts/make-test-bags.sh " URDFSNAP_BINARY_DIR "/bench-bags --large";
    std::fprintf(stderr, "urdfsnap_mcap_bench: making %s (%s)\n", bag.c_str(), make.c_str());
    if (std::system(make.c_str()) != 0) return 2;
  }
  try {
    const double megabytes = std::filesystem::file_size(bag) / 1e6;
    std::printf("%s: %.0f MB\n", bag.c_str(), megabytes);
    for (int run = 0; run < 3; ++run) {
      const auto start = std::chrono::steady_clock::now();
      std::int64_t messages = 0;
      bag::ReadJointStates(bag, bag::kDefaultJointStateTopic,
                           [&](const bag::BagJointState&) { ++messages; });
      const double seconds = Seconds(start);
      std::printf("ReadJointStates: %lld messages in %.2f s: %.0f MB/s of bag, %.0f messages/s\n",
                  static_cast<long long>(messages), seconds, megabytes / seconds,
                  messages / seconds);
    }
    const auto start = std::chrono::steady_clock::now();
    Warnings warnings;
    const motion::Trajectory trajectory = motion::ReadTrajectory(bag, {}, warnings);
    const double seconds = Seconds(start);
    std::printf("ReadTrajectory: %zu joints, %.1f s long, in %.2f s: %.0f MB/s of bag\n",
                trajectory.tracks.size(), trajectory.EndTime(), seconds, megabytes / seconds);
    std::printf("peak memory: %.1f MiB (the trajectory itself: %.1f MiB)\n", PeakMiB(),
                trajectory.tracks.size() * trajectory.tracks[0].times.size() * 16 / 1048576.0);
  } catch (const Error& e) {
    std::fprintf(stderr, "urdfsnap_mcap_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
