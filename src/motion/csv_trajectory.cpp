// ParseCsvTrajectory: line by line, fields split at commas, numbers through common/number_text.
#include "motion/csv_trajectory.h"

#include <algorithm>
#include <optional>
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

// The columns of the header row: which is time (none: rows are the time base), and which track
// each joint column feeds.
struct Columns {
  int time = -1;
  std::vector<std::size_t> track;   // per column; time's entry is unused
};

Columns ReadHeader(const std::vector<std::string_view>& fields, const SourceLocation& where,
                   Trajectory& trajectory) {
  Columns columns;
  for (std::size_t c = 0; c < fields.size(); ++c) {
    const std::string name = Unquoted(fields[c]);
    if (name.empty()) throw Error(where, "column " + std::to_string(c + 1) + " of the header has no name");
    const bool duplicate = (name == "time" && columns.time >= 0) ||
                           std::any_of(trajectory.tracks.begin(), trajectory.tracks.end(),
                                       [&](const JointTrack& track) { return track.joint == name; });
    if (duplicate) throw Error(where, "column '" + name + "' appears twice in the header");
    if (name == "time") {
      columns.time = static_cast<int>(c);
      columns.track.push_back(0);
    } else {
      columns.track.push_back(trajectory.tracks.size());
      trajectory.tracks.push_back(JointTrack{name, {}, {}, where.ToString()});
    }
  }
  if (trajectory.tracks.empty()) {
    throw Error(where, "the header names no joint columns (expected time,<joint>,<joint>...)");
  }
  trajectory.time_base = columns.time >= 0 ? TimeBase::kSeconds : TimeBase::kRows;
  return columns;
}

// A data row's numbers, one per column.
std::vector<double> ReadRow(const std::vector<std::string_view>& fields, const Columns& columns,
                            const SourceLocation& where, const Trajectory& trajectory) {
  if (fields.size() != columns.track.size()) {
    throw Error(where, std::to_string(fields.size()) + " fields, but the header has " +
                           std::to_string(columns.track.size()) + " columns");
  }
  std::vector<double> values(fields.size());
  for (std::size_t c = 0; c < fields.size(); ++c) {
    if (!ParseNumber(fields[c], values[c])) {
      const std::string column =
          static_cast<int>(c) == columns.time ? "time" : trajectory.tracks[columns.track[c]].joint;
      throw Error(where, "column '" + column + "': expected a finite number, got '" + std::string(fields[c]) + "'");
    }
  }
  return values;
}

}  // namespace

Trajectory ParseCsvTrajectory(std::string_view text, const std::string& path) {
  Trajectory trajectory;
  trajectory.source = path;
  std::optional<Columns> columns;   // once the header is read
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
    if (!columns) {
      columns = ReadHeader(Fields(line), where, trajectory);
      continue;
    }
    const std::vector<double> values = ReadRow(Fields(line), *columns, where, trajectory);
    double time = rows;
    if (columns->time >= 0) {
      time = values[columns->time];
      if (rows == 0) first_time = time;
      if (rows > 0 && time <= previous_time) {
        throw Error(where, "time " + FormatNumber(time) + " is not after the previous row's " +
                               FormatNumber(previous_time) + " (times must increase)");
      }
      previous_time = time;
      time -= first_time;
    }
    for (std::size_t c = 0; c < values.size(); ++c) {
      if (static_cast<int>(c) == columns->time) continue;
      JointTrack& track = trajectory.tracks[columns->track[c]];
      track.times.push_back(time);
      track.positions.push_back(values[c]);
    }
    ++rows;
  }
  if (!columns) throw Error(SourceLocation{path, 0}, "no header row (expected time,<joint>,<joint>...)");
  if (rows == 0) throw Error(SourceLocation{path, 0}, "no rows after the header: an empty trajectory");
  return trajectory;
}

}  // namespace urdfsnap::motion
