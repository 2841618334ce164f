// How `urdfsnap render` makes one frame of an animation byte for byte: the options that pin the
// frame's camera (--yaw, --pitch, --distance, --focal: the fitted, turned view) and its pose (-j
// for each joint), added to the animation's own model, view and display options without --fit.
#pragma once

#include <string>
#include <vector>

#include "model/robot.h"
#include "scene/orbit_view.h"

namespace urdfsnap::animation {

// The words to give `render` for a frame showing `positions` (one per robot joint, as
// AnimationFrames::Positions gives them) through `view`: "--yaw=Y --pitch=P --distance=D
// --focal=X,Y,Z -j NAME=VALUE ...", numbers in their shortest round-trip text so that render reads
// back exactly the same values. Every movable joint that is no mimic is named; a mimic joint only
// where its position is not what its leader makes of it (a trajectory that names it). Words are
// quoted for a POSIX shell where they need it. `clamp` is whether render will clamp -j values
// (false when the animation's options hold --no-clamp); when it would and a position is outside
// its limits (a trajectory drawn as recorded), the words add --no-clamp.
std::vector<std::string> RenderWords(const model::Robot& robot, const std::vector<double>& positions,
                                     const scene::OrbitView& view, bool clamp);

// `words` joined by spaces: one line for a shell.
std::string JoinWords(const std::vector<std::string>& words);

}  // namespace urdfsnap::animation
