// A file name's extension in lower case, for choosing a format by name (".MP4" is ".mp4").
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace urdfsnap {

// ".csv" for "plan.CSV", "" for a name without one.
inline std::string LowerCaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

}  // namespace urdfsnap
