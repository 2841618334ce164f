// Forward kinematics for all links of the sample mrm robot per joint vector, allocation-free
// overload, poses cycling through a fixed set so sin/cos see varied arguments.
// Run: build/urdfsnap_fk_bench (orocos KDL needs 0.29 us for the same pass; the aim is half).
#include <fstream>
#include <random>
#include <sstream>

#include <benchmark/benchmark.h>

#include "model/forward_kinematics.h"
#include "model/joint_values.h"

namespace urdfsnap::model {
namespace {

Robot LoadMrm() {
  const std::string path = URDFSNAP_SOURCE_DIR "/models/mrm_description/urdf/mrm.urdf";
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  Warnings warnings;
  return LoadRobot(text.str(), path, warnings);
}

void BM_MrmForwardKinematicsAllLinks(benchmark::State& state) {
  const Robot robot = LoadMrm();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-3.14, 3.14);
  std::vector<std::vector<double>> poses(256, std::vector<double>(robot.joints().size()));
  for (std::vector<double>& pose : poses) {
    for (double& q : pose) q = angle(random);
  }
  std::vector<Eigen::Isometry3d> X_RL(robot.links().size());
  size_t i = 0;
  for (auto _ : state) {
    ComputeLinkPoses(robot, poses[i++ & 255], X_RL);
    benchmark::DoNotOptimize(X_RL.data());
    benchmark::ClobberMemory();
  }
  state.counters["links"] = static_cast<double>(robot.links().size());
}
BENCHMARK(BM_MrmForwardKinematicsAllLinks);

}  // namespace
}  // namespace urdfsnap::model

BENCHMARK_MAIN();
