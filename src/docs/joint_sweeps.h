// How a movable joint is shown: the links it moves (with its mimic followers), the positions of
// its still pictures and the positions of its sweep animation, a loop through its range.
#pragma once

#include <string>
#include <vector>

#include "model/robot.h"

namespace urdfsnap::docs {

// The joints that follow `joint` through mimic rules, directly or through other mimic joints, in
// document order.
std::vector<int> MimicFollowers(const model::Robot& robot, int joint);

// The links that move when `joint` moves (its child link's subtree and its followers'), in
// Robot::links() order.
std::vector<int> MovingLinks(const model::Robot& robot, int joint);

// A still picture's position, its label and the stem of its file name.
struct StillPose {
  const char* label;
  const char* file_stem;
  double position;      // rad or m
};

// The stills of a joint whose default position is `default_position`: lower limit, default,
// upper limit; for continuous joints a quarter turn back, the default, a quarter turn forward
// and a half turn (the same pose either way).
std::vector<StillPose> StillPoses(const model::Joint& joint, double default_position);

// `frames` positions (frames >= 2) looping from the default through the whole range and back:
// default → upper → lower → default for limited joints, at an even speed (the last frame stops
// one step short of the first, so the animation repeats smoothly); one full turn for continuous
// joints.
std::vector<double> SweepPositions(const model::Joint& joint, double default_position, int frames);

}  // namespace urdfsnap::docs
