// The one error type every stage throws: a message that already names the culprit and, when the
// input has one, its location ("robot.urdf:12: joint 'elbow' has no <limit>").
// The command line prints it as "urdfsnap: error: <what()>" and exits with status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace urdfsnap {

// Where in an input file something is; line 0 means "the file as a whole".
struct SourceLocation {
  std::string file;
  int line = 0;

  // "file:line", "file", or "" when nothing is known.
  std::string ToString() const;
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  // Prefixes the message with "file:line: " (or "file: " when the line is unknown).
  Error(const SourceLocation& where, const std::string& message);
};

}  // namespace urdfsnap
