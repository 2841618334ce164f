// Fuzz target: joint files, YAML or JSON (the first byte picks which), then the values resolved
// against a small robot with every joint type and a mimic joint (fuzz_robot.h). Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "fuzz_robot.h"
#include "model/joint_values.h"
#include "model/robot.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  static Warnings load_warnings;
  static const model::Robot robot = model::LoadRobot(fuzz::kFuzzRobot, "robot.urdf", load_warnings);
  if (size == 0) return 0;
  const std::string path = data[0] & 1 ? "pose.json" : "pose.yaml";
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  Warnings warnings;
  try {
    const model::NamedValues values = model::ParseJointFile(text, path);
    model::ResolveJointPositions(robot, values, (data[0] & 2) != 0, warnings);
  } catch (const Error&) {
  }
  return 0;
}
