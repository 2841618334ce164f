// The joint table and link names of /api/robot, built with nlohmann::json.
#include "serve/page_robot_json.h"

#include <numbers>

#include <nlohmann/json.hpp>

#include "model/joint_values.h"

namespace urdfsnap::serve {

std::string PageRobotJson(const model::Robot& robot, const std::vector<std::string>& warnings) {
  // joint_state_publisher's start values are what ResolveJointPositions gives for no values
  Warnings ignored;
  const std::vector<double> defaults = model::ResolveJointPositions(robot, {}, true, ignored);
  nlohmann::json joints = nlohmann::json::array();
  const auto& all = robot.joints();
  for (size_t j = 0; j < all.size(); ++j) {
    const model::Joint& joint = all[j];
    if (!joint.IsMovable()) continue;
    const bool continuous = joint.type == model::JointType::kContinuous;
    nlohmann::json mimic = nullptr;
    if (joint.mimic_leader >= 0) {
      mimic = {{"joint", all[joint.mimic_leader].name},
               {"multiplier", joint.mimic_multiplier},
               {"offset", joint.mimic_offset}};
    }
    joints.push_back({{"name", joint.name},
                      {"type", model::JointTypeName(joint.type)},
                      {"lower", continuous ? -std::numbers::pi : joint.lower},
                      {"upper", continuous ? std::numbers::pi : joint.upper},
                      {"default", defaults[j]},
                      {"mimic", mimic}});
  }
  const nlohmann::json robot_json = {
      {"name", robot.name()}, {"joints", joints}, {"links", robot.LinkNames()}, {"warnings", warnings}};
  // names come from the URDF: replace invalid UTF-8 rather than throw
  return robot_json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace urdfsnap::serve
