// Fuzz target: URDF text through urdfsnap's checks and urdfdom (LoadRobot), then everything that
// works on a loaded robot without GL: the `info` description, joint defaults, forward kinematics,
// the scene (meshes allowed to be missing) and --fit. Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "fuzz_work_dir.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"
#include "model/robot.h"
#include "model/robot_description.h"
#include "scene/robot_scene.h"
#include "scene/view_fitting.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Warnings warnings;
  try {
    const model::Robot robot = model::LoadRobot(text, "robot.urdf", warnings);
    model::DescribeRobot(robot);
    const std::vector<double> positions = model::ResolveJointPositions(robot, {}, true, warnings);
    scene::SceneOptions options;
    options.model_file = "robot.urdf";
    options.allow_missing_meshes = true;
    options.tf.enabled = true;
    options.show_collision = true;
    const scene::Scene scene =
        scene::RobotScene(robot, options, warnings).Pose(model::ComputeLinkPoses(robot, positions));
    scene::FitView(scene, scene::OrbitView{}, 4.0 / 3.0, false);
  } catch (const Error&) {
  }
  return 0;
}
