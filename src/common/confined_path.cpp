// ResolveInside: std::filesystem::weakly_canonical on both sides, then a prefix test by path
// components.
#include "common/confined_path.h"

#include <filesystem>
#include <system_error>

#include "common/error.h"

namespace urdfsnap {

namespace fs = std::filesystem;

std::string ResolveInside(const std::string& folder, const std::string& path) {
  std::error_code error;
  const fs::path base = fs::weakly_canonical(fs::absolute(folder.empty() ? "." : folder, error), error);
  if (error) return "";
  const fs::path resolved = fs::weakly_canonical(base / path, error);
  if (error) return "";
  // component by component: "/a/bc" is not inside "/a/b"
  auto at = resolved.begin();
  for (const fs::path& part : base) {
    if (part.empty()) continue;  // the trailing "" of "/a/b/"
    if (at == resolved.end() || *at != part) return "";
    ++at;
  }
  return resolved.string();
}

std::string ConfinePath(const std::string& folder, const std::string& path, const std::string& where) {
  std::string resolved = ResolveInside(folder, path);
  if (resolved.empty()) {
    throw Error(where + ": '" + path + "' leads outside " + (folder.empty() ? "." : folder) +
                " (paths in this file must stay inside its folder)");
  }
  return resolved;
}

std::string ConfineRegularFile(const std::string& folder, const std::string& path, const std::string& where) {
  std::string resolved = ConfinePath(folder, path, where);
  std::error_code error;
  if (!fs::is_regular_file(resolved, error)) {
    throw Error(where + ": '" + path + "' is not a regular file" +
                (fs::exists(resolved, error) ? "" : " (it is not there)"));
  }
  return resolved;
}

}  // namespace urdfsnap
