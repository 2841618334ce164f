// A collector for warnings: stages add to it, the command line prints each distinct message once
// as "urdfsnap: warning: ..." (and --strict turns the first one into an error); and the one wording
// of an option that does nothing where it was given.
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

// An option (or suite key) given where it does nothing: "OPTION is ignored: WHY", so that no
// command drops one silently ("--clamp is ignored: it clamps a --trajectory's values, and ...").
void WarnIgnored(Warnings& warnings, const std::string& option, const std::string& why);

}  // namespace urdfsnap
