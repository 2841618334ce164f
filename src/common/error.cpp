// Formatting of located error messages.
#include "common/error.h"

namespace urdfsnap {

std::string SourceLocation::ToString() const {
  if (file.empty()) return {};
  if (line <= 0) return file;
  return file + ":" + std::to_string(line);
}

static std::string Located(const SourceLocation& where, const std::string& message) {
  const std::string at = where.ToString();
  return at.empty() ? message : at + ": " + message;
}

Error::Error(const SourceLocation& where, const std::string& message)
    : std::runtime_error(Located(where, message)) {}

}  // namespace urdfsnap
