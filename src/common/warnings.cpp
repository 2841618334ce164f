// Deduplicating warning collector.
#include "common/warnings.h"

#include <algorithm>

namespace urdfsnap {

void Warnings::Add(const std::string& message) {
  if (std::find(messages_.begin(), messages_.end(), message) == messages_.end()) {
    messages_.push_back(message);
  }
}

}  // namespace urdfsnap
