// `urdfsnap info`: the robot's links, joints (type, axis, limits, mimic) and tree.
#include <memory>

#include "cli/command.h"
#include "cli/model_source.h"
#include "request/model_request.h"
#include "model/robot_description.h"

namespace urdfsnap::cli {

void AddInfoCommand(CLI::App& app) {
  auto model = std::make_shared<ModelSource>();
  CLI::App* cmd = app.add_subcommand("info", "Print a robot's links, joints with type, axis and limits, and its tree");
  model->AddOptions(*cmd);
  cmd->callback([model] {
    Warnings warnings;
    std::shared_ptr<const model::Robot> robot;
    try {
      robot = request::LoadModel(model->ToRequest(), warnings).robot;
    } catch (...) {
      PrintWarningsBeforeError(warnings);
      throw;
    }
    PrintWarnings(warnings);
    WriteToStdout(model::DescribeRobot(*robot));
  });
}

}  // namespace urdfsnap::cli
