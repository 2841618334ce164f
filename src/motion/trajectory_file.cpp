// ReadTrajectory: format detection, bounded reading of text files, dispatch to the readers.
#include "motion/trajectory_file.h"

#include <filesystem>
#include <fstream>

#include "common/error.h"
#include "common/file_extension.h"
#include "common/file_reading.h"
#include "motion/bag_trajectory.h"
#include "motion/csv_trajectory.h"
#include "motion/ros_message_trajectory.h"

namespace urdfsnap::motion {
namespace {

constexpr char kMcapMagic[] = "\x89MCAP0\r\n";
constexpr char kSqliteHeader[] = "SQLite format 3";  // a rosbag2 .db3 file

}  // namespace

TrajectoryFormat DetectTrajectoryFormat(const std::string& path, std::string_view head) {
  const std::string extension = LowerCaseExtension(path);
  if (extension == ".csv") return TrajectoryFormat::kCsv;
  if (extension == ".yaml" || extension == ".yml" || extension == ".json") {
    return TrajectoryFormat::kRosMessages;
  }
  if (extension == ".mcap" || extension == ".db3" ||
      head.starts_with(std::string_view(kMcapMagic, 8)) || head.starts_with(kSqliteHeader)) {
    return TrajectoryFormat::kBag;
  }
  const std::string_view first_line = head.substr(0, head.find('\n'));
  if (first_line.find(',') != std::string_view::npos &&
      first_line.find(':') == std::string_view::npos) {
    return TrajectoryFormat::kCsv;
  }
  return TrajectoryFormat::kRosMessages;
}

Trajectory ParseTrajectoryText(std::string_view text, const std::string& path) {
  if (DetectTrajectoryFormat(path, text) == TrajectoryFormat::kCsv) {
    return ParseCsvTrajectory(text, path);
  }
  return ParseRosMessageTrajectory(text, path);
}

bool IsBag(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return true;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  char head[16];
  std::ifstream file(path, std::ios::binary);
  file.read(head, sizeof head);
  return DetectTrajectoryFormat(path, std::string_view(head, static_cast<std::size_t>(file.gcount()))) ==
         TrajectoryFormat::kBag;
}

Trajectory ReadTrajectory(const std::string& path, const TrajectoryOptions& options,
                          Warnings& warnings) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    return ReadBagTrajectory(path, options.topic, warnings);  // a rosbag2 folder
  }
  const auto read_text = [&] {
    try {
      return ReadFileBounded(path);
    } catch (const FileReadError& e) {
      throw Error(SourceLocation{path, 0}, std::string("cannot read the trajectory: ") + e.what());
    }
  };
  // a pipe (`ros2 topic echo ... | urdfsnap animate --trajectory /dev/stdin`) can be read once:
  // its text first, the format from that
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    const std::string text = read_text();
    if (DetectTrajectoryFormat(path, text) == TrajectoryFormat::kBag) {
      throw Error(path + ": a bag must be a file (urdfsnap seeks in it), not a pipe or device");
    }
    return ParseTrajectoryText(text, path);
  }
  char head[256];
  std::ifstream file(path, std::ios::binary);
  file.read(head, sizeof head);
  const std::string_view head_text(head, static_cast<std::size_t>(file.gcount()));
  if (DetectTrajectoryFormat(path, head_text) == TrajectoryFormat::kBag) {
    return ReadBagTrajectory(path, options.topic, warnings);
  }
  return ParseTrajectoryText(read_text(), path);
}

}  // namespace urdfsnap::motion
