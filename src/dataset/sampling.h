// What one dataset sample shows: random joint positions within the robot's limits, and a camera
// on a sphere around the robot looking at its centre.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "dataset/sample_random.h"
#include "model/robot.h"

namespace urdfsnap::dataset {

// A closed interval [low, high].
struct Interval {
  double low = 0;
  double high = 0;
};

// One position per robot joint: each revolute and prismatic joint uniform within its limits, each
// continuous joint uniform over a full turn [−π, π), mimic joints following their leader (through
// model::ResolveJointPositions, whose warnings go to `warnings`), others at 0.
std::vector<double> SampleJointPositions(const model::Robot& robot, SampleRandom& random, Warnings& warnings);

// A camera's optical frame (z forward, x right, y down) at `distance` metres from `centre`, at
// `elevation_deg` degrees above the horizontal plane (+z up) and a uniform azimuth, looking at
// `centre` with no roll (x horizontal).
Eigen::Isometry3d SampleCameraPose(const Eigen::Vector3d& centre, Interval distance, Interval elevation_deg,
                                   SampleRandom& random);

}  // namespace urdfsnap::dataset
