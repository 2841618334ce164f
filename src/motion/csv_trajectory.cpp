// ParseCsvTrajectory: line by line, fields split at commas, numbers through common/number_text.
#include "motion/csv_trajectory.h"

#include <algorithm>
#include <vector>

#include "common/error.h"
#include "common/number_text.h"

namespace urdfsnap::motion {
namespace {

std::string_view Trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> Fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(Trimmed(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::string Unquoted(std::string_view field) {
  if (field.size() >= 2 && field.front() == '"' && field.back() == '"') {
    field = field.substr(1, field.size() - 2);
  }
  return std::string(field);
}

}  // namespace

Trajectory ParseCsvTrajectory(std::string_view text, const std::string& path) {
  Trajectory trajectory;
  trajectory.source = path;
  int time_column = -1;
  std::vector<std::size_t> track_of_column;  // for joint columns; time's entry is unused
  double first_time = 0, previous_time = 0;
  int rows = 0;
  int line_number = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = Trimmed(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    const SourceLocation where{path, line_number};
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> fields = Fields(line);

    if (track_of_column.empty()) {  // the header
      for (std::size_t c = 0; c < fields.size(); ++c) {
        const std::string name = Unquoted(fields[c]);
        if (name.empty()) {
          throw Error(where, "column " + std::to_string(c + 1) + " of the header has no name");
        }
        const bool duplicate =
            (name == "time" && time_column >= 0) ||
            std::any_of(trajectory.tracks.begin(), trajectory.tracks.end(),
                        [&](const JointTrack& track) { return track.joint == name; });
        if (duplicate) throw Error(where, "column '" + name + "' appears twice in the header");
        if (name == "time") {
          time_column = static_cast<int>(c);
          track_of_column.push_back(0);
        } else {
          track_of_column.push_back(trajectory.tracks.size());
          trajectory.tracks.push_back(JointTrack{name, {}, {}, where.ToString()});
        }
      }
      if (trajectory.tracks.empty()) {
        throw Error(where, "the header names no joint columns (expected time,<joint>,<joint>...)");
      }
      trajectory.time_base = time_column >= 0 ? TimeBase::kSeconds : TimeBase::kRows;
      continue;
    }

    if (fields.size() != track_of_column.size()) {
      throw Error(where, std::to_string(fields.size()) + " fields, but the header has " +
                             std::to_string(track_of_column.size()) + " columns");
    }
    std::vector<double> values(fields.size());
    for (std::size_t c = 0; c < fields.size(); ++c) {
      if (!ParseNumber(fields[c], values[c])) {
        const std::string column = static_cast<int>(c) == time_column
                                       ? "time"
                                       : trajectory.tracks[track_of_column[c]].joint;
        throw Error(where, "column '" + column + "': expected a finite number, got '" +
                               std::string(fields[c]) + "'");
      }
    }
    double time = rows;
    if (time_column >= 0) {
      time = values[time_column];
      if (rows == 0) first_time = time;
      if (rows > 0 && time <= previous_time) {
        throw Error(where, "time " + FormatNumber(time) + " is not after the previous row's " +
                               FormatNumber(previous_time) + " (times must increase)");
      }
      previous_time = time;
      time -= first_time;
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
      if (static_cast<int>(c) == time_column) continue;
      JointTrack& track = trajectory.tracks[track_of_column[c]];
      track.times.push_back(time);
      track.positions.push_back(values[c]);
    }
    ++rows;
  }
  if (track_of_column.empty())
    throw Error(SourceLocation{path, 0}, "no header row (expected time,<joint>,<joint>...)");
  if (rows == 0)
    throw Error(SourceLocation{path, 0}, "no rows after the header: an empty trajectory");
  return trajectory;
}

}  // namespace urdfsnap::motion
