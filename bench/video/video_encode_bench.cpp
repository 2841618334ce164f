// Encoding speed of each animation format at 640x480 (frames/s, as Google Benchmark's items per
// second) on synthetic robot-like frames (tests/video/synthetic_frames.h), the frames made before
// timing, with the processor time of all the encoder's threads per frame (cpu_ms_per_frame: the
// cost on a shared machine, where wall time depends on the load); and, with --memory, the peak
// memory of a whole encode of N frames, to show that it does not grow with the animation's length.
// usage: urdfsnap_video_bench [Google Benchmark flags]
//        urdfsnap_video_bench --memory FORMAT FRAMES   (FORMAT: mp4 webm gif webp png)
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "common/error.h"
#include "synthetic_frames.h"
#include "video/encode_frames.h"
#include "video/open_frame_encoder.h"

namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 640, kHeight = 480;
constexpr int kDistinctFrames = 60;  // cycled: encoders see motion, the benchmark sees no drawing

const std::vector<urdfsnap::image::Image>& Frames() {
  static const std::vector<urdfsnap::image::Image> frames = [] {
    std::vector<urdfsnap::image::Image> made;
    for (int i = 0; i < kDistinctFrames; ++i) {
      made.push_back(urdfsnap::test::SyntheticFrame(kWidth, kHeight, i));
    }
    return made;
  }();
  return frames;
}

// The output for `format` in a folder of its own, emptied first (PNG sizes add up its files).
std::string OutputPath(const std::string& format) {
  const fs::path folder = fs::temp_directory_path() / "urdfsnap-video-bench";
  fs::remove_all(folder / "frames");
  fs::create_directories(folder / "frames");
  return (folder / (format == "png" ? "frames/%05d.png" : "robot." + format)).string();
}

// Encodes `count` frames to `format` as `animate` will: frames made on this thread (here copied,
// standing in for the renderer), encoded on a worker (video::EncodeFrames). Returns the output's
// size in bytes (the sequence's total for PNG frames).
std::uintmax_t Encode(const std::string& format, int count) {
  urdfsnap::Warnings warnings;
  const std::string path = OutputPath(format);
  const auto encoder = urdfsnap::video::OpenFrameEncoder(path, {kWidth, kHeight, 30}, warnings);
  urdfsnap::video::EncodeFrames(
      count,
      [](std::int64_t k, urdfsnap::image::Image& frame) { frame = Frames()[k % kDistinctFrames]; },
      *encoder);
  if (format != "png") return fs::file_size(path);
  std::uintmax_t total = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path())) {
    total += entry.file_size();
  }
  return total;
}

// Processor time of the whole process (every thread), in milliseconds.
double ProcessCpuMilliseconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& time) { return time.tv_sec * 1e3 + time.tv_usec * 1e-3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

void BM_Encode(benchmark::State& state, const std::string& format) {
  constexpr int kFramesPerRun = 120;
  Frames();
  std::uintmax_t bytes = 0;
  const double cpu_start = ProcessCpuMilliseconds();
  for (auto _ : state) bytes = Encode(format, kFramesPerRun);
  const double frames = double(state.iterations()) * kFramesPerRun;
  state.SetItemsProcessed(static_cast<std::int64_t>(frames));
  state.counters["KiB_per_frame"] = double(bytes) / kFramesPerRun / 1024;
  state.counters["cpu_ms_per_frame"] = (ProcessCpuMilliseconds() - cpu_start) / frames;
}

BENCHMARK_CAPTURE(BM_Encode, png, std::string("png"))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Encode, mp4, std::string("mp4"))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Encode, webm, std::string("webm"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Encode, gif, std::string("gif"))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Encode, webp, std::string("webp"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::strcmp(argv[1], "--memory") == 0) {
    try {
      const std::uintmax_t bytes = Encode(argv[2], std::stoi(argv[3]));
      rusage usage{};
      getrusage(RUSAGE_SELF, &usage);
      std::printf("%s, %s frames at %dx%d: peak memory %.1f MiB, output %.1f MiB\n", argv[2],
                  argv[3], kWidth, kHeight, usage.ru_maxrss / 1024.0, bytes / 1048576.0);
    } catch (const urdfsnap::Error& e) {
      std::fprintf(stderr, "urdfsnap_video_bench: %s\n", e.what());
      return 2;
    }
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
