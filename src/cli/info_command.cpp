// `urdfsnap info`: the robot's links, joints (type, axis, limits, mimic) and tree, as text or
// (--json) as JSON in docs/info.schema.json's format.
#include <memory>

#include "cli/command.h"
#include "cli/model_source.h"
#include "request/model_request.h"
#include "model/robot_description.h"
#include "model/robot_json.h"

namespace urdfsnap::cli {

void AddInfoCommand(CLI::App& app) {
  auto model = std::make_shared<ModelSource>();
  CLI::App* cmd = app.add_subcommand("info", "Print a robot's links, joints with type, axis and limits, and its tree");
  model->AddOptions(*cmd);
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json,
                "Print JSON instead (links, joints with every limit, origins, defaults, masses, "
                "the tree; format in docs/info.schema.json)");
  cmd->callback([model, json] {
    Warnings warnings;
    std::shared_ptr<const model::Robot> robot;
    try {
      robot = request::LoadModel(model->ToRequest(), warnings).robot;
    } catch (...) {
      PrintWarningsBeforeError(warnings);
      throw;
    }
    PrintWarnings(warnings);
    WriteToStdout(*json ? model::DescribeRobotJson(*robot) : model::DescribeRobot(*robot));
  });
}

}  // namespace urdfsnap::cli
