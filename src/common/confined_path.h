// Paths read from a file that may come from elsewhere (a results file from another machine's CI
// job, a committed docs page) are kept inside the folder that file describes: after every
// symbolic link is resolved the path must still lie in that folder, so that an edited file cannot
// make urdfsnap read (and copy into its outputs) /etc/passwd or a file in the user's home.
#pragma once

#include <string>

namespace urdfsnap {

// `path` resolved against `folder` (when relative) with every symbolic link followed, or the
// empty string when it leads outside `folder` (itself resolved the same way; `folder` itself
// counts as inside). Nothing need exist.
std::string ResolveInside(const std::string& folder, const std::string& path);

// ResolveInside, or throws urdfsnap::Error "WHERE: 'PATH' leads outside FOLDER" (WHERE names the
// file and key the path was read from, "r.json: report_dir").
std::string ConfinePath(const std::string& folder, const std::string& path, const std::string& where);

// ConfinePath for a file that is read next: it must also be a regular file (not a folder, pipe or
// device, which could block a read forever or never end). Throws urdfsnap::Error
// "WHERE: 'PATH' is not a regular file" otherwise.
std::string ConfineRegularFile(const std::string& folder, const std::string& path, const std::string& where);

}  // namespace urdfsnap
