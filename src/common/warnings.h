// A collector for warnings: stages add to it, the command line prints each distinct message once
// as "urdfsnap: warning: ..." (and --strict turns the first one into an error).
#pragma once

#include <string>
#include <vector>

namespace urdfsnap {

class Warnings {
 public:
  // Records a warning; an identical message already recorded is ignored.
  void Add(const std::string& message);

  const std::vector<std::string>& messages() const { return messages_; }
  bool empty() const { return messages_.empty(); }
  void Clear() { messages_.clear(); }

 private:
  std::vector<std::string> messages_;
};

}  // namespace urdfsnap
