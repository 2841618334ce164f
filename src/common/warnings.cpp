// Deduplicating warning collector, and the wording of an ignored option.
#include "common/warnings.h"

#include <algorithm>

namespace urdfsnap {

void Warnings::Add(const std::string& message) {
  if (std::find(messages_.begin(), messages_.end(), message) == messages_.end()) {
    messages_.push_back(message);
  }
}

void WarnIgnored(Warnings& warnings, const std::string& option, const std::string& why) {
  warnings.Add(option + " is ignored: " + why);
}

}  // namespace urdfsnap
