// Trajectories as CSV tables: a header row `time,<joint>,<joint>...` (time in seconds, then radians
// or metres), one row per waypoint; without a `time` column each row is one frame.
#pragma once

#include <string>
#include <string_view>

#include "motion/trajectory.h"

namespace urdfsnap::motion {

// Parses a CSV trajectory. Blank lines and lines starting with '#' are skipped; fields may be
// padded with spaces and the header's names quoted ("elbow"). Times count from the first row (so
// a logger's absolute times work) and must increase. Throws Error "PATH:LINE: ..." for a missing
// or duplicate column name, a row with too few or too many fields, a field that is not a finite
// number, a time not after the previous row's, or a table without rows.
Trajectory ParseCsvTrajectory(std::string_view text, const std::string& path);

}  // namespace urdfsnap::motion
