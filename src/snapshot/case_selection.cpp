// SelectCases: names checked against the suite first, then the shard's share taken.
#include "snapshot/case_selection.h"

#include <set>

#include "common/error.h"
#include "shard/shard_assignment.h"

namespace urdfsnap::snapshot {

namespace {

// "a, b, c" or, for a long suite, its first names and the count.
std::string KnownNames(const Suite& suite) {
  constexpr std::size_t kListed = 20;
  std::string known;
  for (std::size_t i = 0; i < suite.cases.size() && i < kListed; ++i) {
    known += (i == 0 ? "" : ", ") + suite.cases[i].name;
  }
  if (suite.cases.size() > kListed) known += ", ... (" + std::to_string(suite.cases.size()) + " cases)";
  return known;
}

}  // namespace

std::vector<const SnapshotCase*> SelectCases(const Suite& suite, const std::vector<std::string>& names,
                                             shard::Shard shard) {
  std::set<std::string> wanted(names.begin(), names.end());
  std::vector<const SnapshotCase*> selected;
  for (const SnapshotCase& c : suite.cases) {
    const bool named = names.empty() || wanted.erase(c.name) > 0;
    if (named && shard::InShard(c.name, shard)) selected.push_back(&c);
  }
  if (!wanted.empty()) {
    throw Error(suite.path + ": no case named '" + *wanted.begin() + "' (cases: " + KnownNames(suite) + ")");
  }
  return selected;
}

}  // namespace urdfsnap::snapshot
