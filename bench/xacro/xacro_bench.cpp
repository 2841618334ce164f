// The xacro benchmark: whole-process time of `urdfsnap xacro` on the tutorial robot (and of this
// binary expanding it, a process that links only the xacro library, to separate the program's
// start-up from the expansion), and the in-process expansion time of synthetic documents with
// 500, 2,000 and 8,000 macro calls (to show linear growth). Medians of repeated runs.
//
// usage: xacro_bench URDFSNAP_BINARY TUTORIAL_XACRO
//        xacro_bench --expand FILE     (used by the benchmark itself: expand FILE to stdout)
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "synthetic_xacro.h"
#include "xacro/xacro.h"

namespace {

using Clock = std::chrono::steady_clock;

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// one run of `binary verb file` with output to /dev/null, in seconds
double RunProcess(const std::string& binary, const char* verb, const std::string& file) {
  const auto start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(127);
    execl(binary.c_str(), binary.c_str(), verb, file.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "xacro_bench: '%s %s %s' failed\n", binary.c_str(), verb, file.c_str());
    std::exit(1);
  }
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double MedianProcessTime(const std::string& binary, const char* verb, const std::string& file) {
  std::vector<double> runs;
  for (int k = 0; k < 21; ++k) runs.push_back(RunProcess(binary, verb, file));
  return Median(runs);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--expand") {
    urdfsnap::Warnings warnings;
    const std::string xml = urdfsnap::xacro::ExpandFile(argv[2], {}, warnings).xml;
    std::fwrite(xml.data(), 1, xml.size(), stdout);
    return 0;
  }
  if (argc != 3) {
    std::fprintf(stderr, "usage: xacro_bench URDFSNAP_BINARY TUTORIAL_XACRO\n");
    return 2;
  }
  std::printf("tutorial robot, whole process: urdfsnap xacro %.2f ms; xacro library alone %.2f ms (medians of 21)\n",
              MedianProcessTime(argv[1], "xacro", argv[2]) * 1e3,
              MedianProcessTime("/proc/self/exe", "--expand", argv[2]) * 1e3);
  {
    std::vector<double> times;
    for (int k = 0; k < 21; ++k) {
      urdfsnap::Warnings warnings;
      const auto start = Clock::now();
      urdfsnap::xacro::ExpandFile(argv[2], {}, warnings);
      times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    std::printf("tutorial robot, in process: %.3f ms\n", Median(times) * 1e3);
  }

  const auto dir = std::filesystem::temp_directory_path() / ("xacro_bench." + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  double per_call_500 = 0;
  for (int calls : {500, 2000, 8000}) {
    const auto file = dir / ("synthetic_" + std::to_string(calls) + ".xacro");
    std::ofstream(file) << urdfsnap::bench::SyntheticXacro(calls);
    std::vector<double> times;
    size_t bytes = 0;
    for (int k = 0; k < 5; ++k) {
      urdfsnap::Warnings warnings;
      const auto start = Clock::now();
      bytes = urdfsnap::xacro::ExpandFile(file.string(), {}, warnings).xml.size();
      times.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    }
    const double t = Median(times);
    if (calls == 500) per_call_500 = t / calls;
    std::printf("%5d macro calls: %.1f ms in process (%zu KB out), %.2f us/call (%.2fx the 500-call rate)\n",
                calls, t * 1e3, bytes >> 10, t / calls * 1e6, t / calls / per_call_500);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
