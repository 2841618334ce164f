// Synthetic xacro robots for benchmarks: N macro calls, each expanding a link (visual, inertial)
// and a joint with a block argument and seven `${}` expressions, as in the reference timings of
// ../shared/xacro-conformance/FEATURES.md.
#pragma once

#include <string>

namespace urdfsnap::bench {

// The text of a xacro document with `calls` macro calls (a chain of links and joints).
std::string SyntheticXacro(int calls);

}  // namespace urdfsnap::bench
