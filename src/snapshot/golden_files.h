// Writing a case's goldens for `snapshot update`: the colour PNG with the camera it was drawn with
// (snapshot/golden_camera.h), and the depth (16-bit mm) and labels (16-bit, with the link names in
// FILE.json beside it) PNGs of cases that have them; only those that are missing or no longer
// match (the camera also when it is missing or another), unless forced.
#pragma once

#include <string>
#include <vector>

#include "common/output_plan.h"
#include "model/robot.h"
#include "snapshot/case_check.h"

namespace urdfsnap::snapshot {

// Adds every golden file of `c` (colour, depth, labels and its link names) to `outputs`.
void PlanGoldens(OutputPlan& outputs, const SnapshotCase& c);

// Writes the goldens of `c` from `result` (a CheckCase result that is not kError) whose own
// comparison did not pass, or all with `force`, through `outputs` (planned with PlanGoldens; in
// place at its Commit). `robot` is the case's robot (the labels golden's link names). Returns the
// paths written. Throws urdfsnap::Error naming a file that cannot be written.
std::vector<std::string> WriteGoldens(OutputPlan& outputs, const SnapshotCase& c, const CaseResult& result, bool force,
                                      const model::Robot& robot);

}  // namespace urdfsnap::snapshot
