// Reading a trajectory file of any kind urdfsnap animates, the format taken from the extension
// (.csv, .yaml/.yml, .json, .mcap, .db3, a rosbag2 folder) or, for other names, from the content.
#pragma once

#include <string>
#include <string_view>

#include "bag/joint_state_bag.h"
#include "common/warnings.h"
#include "motion/trajectory.h"

namespace urdfsnap::motion {

enum class TrajectoryFormat {
  kCsv,          // csv_trajectory.h
  kRosMessages,  // YAML or JSON, ros_message_trajectory.h
  kBag,          // MCAP or SQLite (.db3) file or rosbag2 folder, bag_trajectory.h
};

struct TrajectoryOptions {
  std::string topic = bag::kDefaultJointStateTopic;  // the JointState topic of a bag
};

// The format of the file at `path` whose first bytes are `head`: by extension, else MCAP's magic
// or SQLite's header makes a bag, a first line with commas and no colon a CSV table, anything else YAML or JSON.
TrajectoryFormat DetectTrajectoryFormat(const std::string& path, std::string_view head);

// Whether `path` is a bag: a rosbag2 folder, or a file DetectTrajectoryFormat takes for one (by
// its extension or first bytes). False for a path that cannot be read.
bool IsBag(const std::string& path);

// Reads the trajectory at `path` (a file, or a rosbag2 folder). Throws Error naming the file and
// the line (or the bag message) for anything wrong, including an empty trajectory; text files are
// read up to common/file_reading's limit.
Trajectory ReadTrajectory(const std::string& path, const TrajectoryOptions& options,
                          Warnings& warnings);

// A CSV, YAML or JSON trajectory from its text; `path` names it and, by its extension, picks the
// format (see DetectTrajectoryFormat). For bags use ReadTrajectory.
Trajectory ParseTrajectoryText(std::string_view text, const std::string& path);

}  // namespace urdfsnap::motion
