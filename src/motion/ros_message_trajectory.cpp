// ParseRosMessageTrajectory: the text split into YAML documents at `---` lines (each parsed alone,
// so a long echo stream is never one tree in memory), each document's message recognised by its
// fields and fed to JointStateTracks point by point or message by message.
#include "motion/ros_message_trajectory.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <optional>
#include <vector>

#include "common/error.h"
#include "common/internal/yaml_reader.h"
#include "motion/joint_state_tracks.h"

namespace urdfsnap::motion {
namespace {

constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;

// One YAML document of the text and the line it starts on (1-based).
struct Document {
  std::string_view text;
  int first_line = 1;
};

// Splits at lines that start a document ("---") or end one ("..."); JSON has no such lines.
std::vector<Document> SplitDocuments(std::string_view text) {
  std::vector<Document> documents;
  std::size_t document_start = 0;
  int document_line = 1, line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view row = text.substr(start, end - start);
    const bool marker = (row.starts_with("---") || row.starts_with("...")) &&
                        (row.size() == 3 || row[3] == ' ' || row[3] == '\t' || row[3] == '\r');
    if (marker) {
      documents.push_back({text.substr(document_start, start - document_start), document_line});
      document_start = end + 1;
      document_line = line + 1;
    }
    start = end + 1;
  }
  if (document_start < text.size()) {
    documents.push_back({text.substr(document_start), document_line});
  }
  return documents;
}

// Reads nodes of one document with its lines counted in the whole file (common's YamlReader), and
// ROS times.
class Reader : public YamlReader {
 public:
  using YamlReader::YamlReader;

  // A builtin_interfaces/Time or Duration ({sec, nanosec}, or ROS 1's {secs, nsecs}), or seconds,
  // in nanoseconds.
  std::int64_t Time(const YAML::Node& node, const char* what) const {
    if (node.IsScalar()) {
      const double seconds = Number(node, what);
      if (std::abs(seconds) > 9e9) Fail(node, std::string(what) + " is out of range");
      return std::llround(seconds * kNanosecondsPerSecond);
    }
    if (!node.IsMap()) Fail(node, std::string(what) + ": expected {sec, nanosec} or seconds");
    const bool ros1 = node["secs"] && !node["sec"];
    const double sec = Number(Field(node, ros1 ? "secs" : "sec", what), std::string(what) + ".sec");
    const double nanosec =
        Number(Field(node, ros1 ? "nsecs" : "nanosec", what), std::string(what) + ".nanosec");
    if (sec != std::trunc(sec) || std::abs(sec) > 9e9 || nanosec != std::trunc(nanosec) ||
        nanosec < 0 || nanosec >= kNanosecondsPerSecond) {
      Fail(node, std::string(what) + ": expected whole seconds and 0 <= nanosec < 1e9");
    }
    return static_cast<std::int64_t>(sec) * kNanosecondsPerSecond +
           static_cast<std::int64_t>(nanosec);
  }
};

enum class Kind { kNone, kTrajectory, kJointStates };

// Adds a JointTrajectory's points, `offset_ns` after the start (segments of a DisplayTrajectory
// follow each other); returns the time of its last point.
std::int64_t AddJointTrajectory(const Reader& reader, const YAML::Node& trajectory,
                                std::int64_t offset_ns, JointStateTracks& tracks) {
  const std::vector<std::string> names =
      reader.Names(reader.Field(trajectory, "joint_names", "the JointTrajectory"), "joint_names");
  const YAML::Node points = reader.Field(trajectory, "points", "the JointTrajectory");
  if (!points.IsSequence()) reader.Fail(points, "'points' is not a list");
  std::int64_t end_ns = offset_ns;
  for (const YAML::Node& point : points) {
    if (!point.IsMap()) reader.Fail(point, "a point that is not a map");
    const std::vector<double> positions =
        reader.Numbers(reader.Field(point, "positions", "the point"), "positions");
    if (positions.empty()) reader.Fail(point, "a point without positions");
    end_ns = offset_ns +
             reader.Time(reader.Field(point, "time_from_start", "the point"), "time_from_start");
    tracks.Add(end_ns, names, positions, [&] { return reader.Where(point).ToString(); });
  }
  return end_ns;
}

void AddJointState(const Reader& reader, const YAML::Node& message, JointStateTracks& tracks) {
  const YAML::Node header = reader.Field(message, "header", "the JointState");
  const std::int64_t stamp = reader.Time(reader.Field(header, "stamp", "header"), "header.stamp");
  tracks.Add(stamp, reader.Names(message["name"], "name"),
             reader.Numbers(message["position"], "position"),
             [&] { return reader.Where(message).ToString(); });
}

}  // namespace

Trajectory ParseRosMessageTrajectory(std::string_view text, const std::string& path) {
  std::optional<JointStateTracks> tracks;
  Kind kind = Kind::kNone;
  // the kind of the first message decides; the other kind after it is an error
  const auto begin = [&](Kind wanted, const Reader& reader, const YAML::Node& node) {
    if (kind == Kind::kTrajectory) {
      reader.Fail(node, wanted == Kind::kTrajectory
                            ? "a second trajectory; urdfsnap animates one (save a single "
                              "message, e.g. with `ros2 topic echo --once`)"
                            : "a JointState message after a trajectory");
    }
    if (kind == Kind::kJointStates && wanted != kind) {
      reader.Fail(node, "a trajectory after JointState messages");
    }
    if (kind == Kind::kNone) {
      tracks.emplace(path,
                     wanted == Kind::kTrajectory ? std::optional<std::int64_t>(0) : std::nullopt);
    }
    kind = wanted;
  };

  const auto add_message = [&](const Reader& reader, const YAML::Node& message) {
    if (!message.IsMap()) reader.Fail(message, "expected a ROS message (a map of fields)");
    if (message["joint_names"] || message["points"]) {
      begin(Kind::kTrajectory, reader, message);
      AddJointTrajectory(reader, message, 0, *tracks);
    } else if (message["joint_trajectory"]) {  // moveit_msgs/RobotTrajectory
      begin(Kind::kTrajectory, reader, message);
      AddJointTrajectory(reader, message["joint_trajectory"], 0, *tracks);
    } else if (message["trajectory"]) {  // moveit_msgs/DisplayTrajectory
      begin(Kind::kTrajectory, reader, message);
      const YAML::Node segments = message["trajectory"];
      if (!segments.IsSequence()) reader.Fail(segments, "'trajectory' is not a list");
      std::int64_t offset_ns = 0;
      for (const YAML::Node& segment : segments) {
        offset_ns = AddJointTrajectory(
            reader, reader.Field(segment, "joint_trajectory", "the RobotTrajectory"), offset_ns,
            *tracks);
      }
    } else if (message["name"] && message["position"]) {
      begin(Kind::kJointStates, reader, message);
      AddJointState(reader, message, *tracks);
    } else {
      reader.Fail(message,
                  "expected a JointTrajectory (joint_names, points), a MoveIt RobotTrajectory or "
                  "DisplayTrajectory, or JointState messages (header, name, position)");
    }
  };

  for (const Document& document : SplitDocuments(text)) {
    const Reader reader(path, document.first_line);
    // yaml-cpp's exceptions (bad syntax, and any a lookup throws) become located errors
    try {
      const YAML::Node root = reader.Load(std::string(document.text));
      if (!root || root.IsNull()) continue;
      if (root.IsSequence()) {
        for (const YAML::Node& message : root) add_message(reader, message);
      } else {
        add_message(reader, root);
      }
    } catch (const YAML::Exception& e) {
      const int line = e.mark.is_null() ? document.first_line : document.first_line + e.mark.line;
      throw Error(SourceLocation{path, line}, "bad YAML: " + e.msg);
    }
  }
  if (!tracks) throw Error(SourceLocation{path, 0}, "no trajectory or JointState message");
  return std::move(*tracks).Finish();
}

}  // namespace urdfsnap::motion
