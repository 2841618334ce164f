// Which cases of a suite a run takes: the ones named on the command line (all when none is), and
// of those the ones its shard owns (by a stable hash of the case name, see shard/).
#pragma once

#include <string>
#include <vector>

#include "shard/shard_spec.h"
#include "snapshot/suite_file.h"

namespace urdfsnap::snapshot {

// The cases of `suite` named in `names` (all when `names` is empty) that belong to `shard`, in
// suite order. Throws urdfsnap::Error "SUITE: no case named 'x' (cases: ...)" for a name the suite
// does not have.
std::vector<const SnapshotCase*> SelectCases(const Suite& suite, const std::vector<std::string>& names,
                                             shard::Shard shard = {});

}  // namespace urdfsnap::snapshot
