// Random names for temporary files and folders beside their final place: the one rule for the
// atomic file writer and the docs page's folder swap.
#pragma once

#include <string>

namespace urdfsnap {

// Six random lower-case letters and digits (from std::random_device), as mkstemp/mkdtemp would
// pick; the callers retry on a name that exists.
std::string RandomSuffix();

}  // namespace urdfsnap
