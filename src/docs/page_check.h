// `urdfsnap docs --check`: a committed page against a fresh one, file by file: the text files
// (README.md, index.html) exactly, the pictures with the snapshot tolerances (a re-render on
// another CPU passes, a moved joint does not), animations exactly.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image_diff.h"

namespace urdfsnap::docs {

// What differs, one line per file: "README.md: line 40 differs: ...", "joints/a/upper.png: max
// delta 96, ...", "joints/b/lower.png: missing from the committed page", "...: not in a fresh
// page". Empty when the committed page is up to date.
std::vector<std::string> ComparePages(const std::filesystem::path& committed, const std::filesystem::path& fresh,
                                      const image::DiffTolerance& tolerance = {});

}  // namespace urdfsnap::docs
