// Fuzz target: joint files, YAML or JSON (the first byte picks which), then the values resolved
// against a small robot with every joint type and a mimic joint. Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "model/joint_values.h"
#include "model/robot.h"

namespace {

constexpr const char* kRobot = R"(<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="a"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="slide" type="prismatic"><parent link="a"/><child link="b"/>
    <limit lower="0.2" upper="0.5" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="b"/><child link="c"/>
    <mimic joint="shoulder" multiplier="-2" offset="0.1"/></joint>
  <joint name="weld" type="fixed"><parent link="c"/><child link="d"/></joint>
</robot>)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  static Warnings load_warnings;
  static const model::Robot robot = model::LoadRobot(kRobot, "robot.urdf", load_warnings);
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
