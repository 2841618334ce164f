// Fuzz target: trajectory text as CSV, YAML or JSON (the first byte picks the file name's
// extension, and its bits the joint rules: clamping, strict joints), then, if it parses, its frame
// plan and a few poses on a small robot (interpolation, clamping and unknown joints with whatever
// came in; fuzz_robot.h). Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "fuzz_robot.h"
#include "model/robot.h"
#include "motion/frame_plan.h"
#include "motion/frame_poses.h"
#include "motion/trajectory_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  static Warnings load_warnings;
  static const model::Robot robot = model::LoadRobot(fuzz::kFuzzRobot, "robot.urdf", load_warnings);
  if (size == 0) return 0;
  static const char* const kNames[] = {"plan.csv", "plan.yaml", "plan.json", "plan.txt"};
  const std::string path = kNames[data[0] % 4];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const motion::Trajectory trajectory = motion::ParseTrajectoryText(text, path);
    Warnings warnings;
    const motion::JointRules rules{(data[0] & 4) != 0, (data[0] & 8) != 0, (data[0] & 16) != 0};
    const motion::FramePoses poses(robot, trajectory, {{"slide", 0.3}}, rules, warnings);
    const motion::FramePlan plan = motion::PlanFrames(trajectory, 7, 1.5);
    for (std::int64_t k = 0; k < plan.frame_count; k += 1 + plan.frame_count / 5) {
      poses.At(plan.TrajectoryTime(k), warnings);
    }
  } catch (const Error&) {
  }
  return 0;
}
