// TF as an animation of a 60 s, 100 Hz recording would use it: a mobile base's odom -> base_link on
// /tf (6000 samples), a sensor mast of static frames on /tf_static and a second robot's tree
// beside them; each 30 fps frame looks up every frame of the tree in the fixed frame (odom), the
// TF display's work, at a time between samples. Building the buffer is measured too.
// Run: build/urdfsnap_tf_bench (the budget is 1 ms per frame).
#include <benchmark/benchmark.h>

#include "tf/tf_buffer.h"

namespace urdfsnap::tf {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;
constexpr int kSamples = 6000;  // 60 s at 100 Hz

std::vector<std::pair<StampedTransform, bool>> Recording() {
  std::vector<std::pair<StampedTransform, bool>> transforms;
  const auto add = [&](std::string parent, std::string child, std::int64_t stamp, double x,
                       double yaw, bool is_static) {
    transforms.push_back({{std::move(parent), std::move(child), stamp, {x, 0, 0.1},
                           Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))},
                          is_static});
  };
  // a mast of 20 static frames, and 10 frames of a second robot
  for (int i = 0; i < 20; ++i) {
    add(i == 0 ? "base_link" : "mast_" + std::to_string(i - 1), "mast_" + std::to_string(i), 0,
        0.05, 0.1, true);
  }
  for (int i = 0; i < 10; ++i) {
    add(i == 0 ? "odom" : "other_" + std::to_string(i - 1), "other_" + std::to_string(i), 0, 0.2,
        0.3, true);
  }
  for (int i = 0; i < kSamples; ++i) {
    add("odom", "base_link", i * kSecond / 100, 0.01 * i, 0.001 * i, false);
  }
  return transforms;
}

void BM_BuildBuffer(benchmark::State& state) {
  const auto recording = Recording();
  for (auto _ : state) {
    TfBuffer buffer;
    for (const auto& [transform, is_static] : recording) buffer.Add(transform, is_static, "bench");
    benchmark::DoNotOptimize(buffer.frames().data());
  }
  state.counters["transforms"] = static_cast<double>(recording.size());
}
BENCHMARK(BM_BuildBuffer)->Unit(benchmark::kMillisecond);

void BM_LookUpEveryFrameInTheFixedFrame(benchmark::State& state) {
  TfBuffer buffer;
  for (const auto& [transform, is_static] : Recording()) buffer.Add(transform, is_static, "bench");
  const std::vector<std::string> frames = buffer.frames();
  std::int64_t k = 0;
  for (auto _ : state) {
    const std::int64_t time = (k++ % 1800) * kSecond / 30 + 1234567;  // frame k at 30 fps
    for (const std::string& frame : frames) {
      benchmark::DoNotOptimize(buffer.Find("odom", frame, time));
    }
  }
  state.counters["frames_looked_up"] = static_cast<double>(frames.size());
}
BENCHMARK(BM_LookUpEveryFrameInTheFixedFrame)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace urdfsnap::tf

BENCHMARK_MAIN();
