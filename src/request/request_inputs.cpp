// AddRequestInputs: three paths of the request, each under the name a user gave it.
#include "request/request_inputs.h"

namespace urdfsnap::request {

void AddRequestInputs(OutputPlan& plan, const RenderRequest& request, const std::string& where) {
  plan.AddInput(request.model.path, where + "the model");
  plan.AddInput(request.joint_file, where + "the joint file");
  plan.AddInput(request.rviz, where + "the .rviz file");
}

}  // namespace urdfsnap::request
