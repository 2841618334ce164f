// FileSafeNames: byte-wise replacement, then numbering of case-insensitive repeats.
#include "docs/file_names.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace urdfsnap::docs {

namespace {

constexpr size_t kMaxLength = 60;

std::string SafeName(const std::string& name) {
  std::string safe;
  for (size_t i = 0; i < name.size() && safe.size() < kMaxLength; ++i) {
    const unsigned char c = name[i];
    const bool kept = (c < 128 && std::isalnum(c)) || c == '_' || c == '-' || (c == '.' && i > 0);
    safe += kept ? static_cast<char>(c) : '_';
  }
  return safe.empty() ? "_" : safe;
}

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

}  // namespace

std::vector<std::string> FileSafeNames(const std::vector<std::string>& names) {
  std::vector<std::string> result;
  std::set<std::string> taken;   // lower case
  for (const std::string& name : names) {
    const std::string base = SafeName(name);
    std::string candidate = base;
    for (int n = 2; !taken.insert(Lower(candidate)).second; ++n) candidate = base + "-" + std::to_string(n);
    result.push_back(candidate);
  }
  return result;
}

}  // namespace urdfsnap::docs
