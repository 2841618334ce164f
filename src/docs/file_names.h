// File and anchor names made from robot names (which URDF lets hold any character): safe on every
// file system and in URLs, and unique on a page even where names differ only in case.
#pragma once

#include <string>
#include <vector>

namespace urdfsnap::docs {

// One name per entry of `names`, in order: ASCII letters, digits, '_', '-' and '.' (not first) kept, any
// other byte '_', at most 60 characters, "_" for an empty name; a name already taken (compared
// without case, as macOS and Windows file systems do) gets "-2", "-3", ... appended.
std::vector<std::string> FileSafeNames(const std::vector<std::string>& names);

}  // namespace urdfsnap::docs
