// The files a render request reads (its model, joint file and .rviz file), named as inputs of a
// command's output plan, so that no output of the command can overwrite one of them.
#pragma once

#include <string>

#include "common/output_plan.h"
#include "request/render_request.h"

namespace urdfsnap::request {

// Adds the model, the joint file and the .rviz file of `request` (those given) to `plan` as
// inputs, their roles starting with `where` (a suite case's "suite.yaml:12: case 'home': ").
void AddRequestInputs(OutputPlan& plan, const RenderRequest& request, const std::string& where = "");

}  // namespace urdfsnap::request
