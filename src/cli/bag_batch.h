// Many bags, one view: `animate a.mcap b.mcap ... -o out/{stem}.mp4` animates each bag with the
// same options in one process, each into the outputs named by its stem. A bag that fails gets its
// error line and the others are still animated; the run then ends with a summary and exit status 2.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace urdfsnap::cli {

// The placeholder in -o (and --depth, --labels) replaced by each bag's stem.
inline constexpr const char* kStemPlaceholder = "{stem}";

// A bag's stem: the file name without its extension (run.mcap → run), or a rosbag2 folder's name.
std::string BagStem(const std::string& bag);

// `pattern` with every {stem} replaced by `stem`.
std::string WithStem(std::string pattern, const std::string& stem);

// Runs `animate_one(bag)` for each of `bags` in order. An urdfsnap::Error from one is printed as
// "urdfsnap: error: ..." and the next bag is run; then a summary line "animated N of M bags; failed:
// a.mcap, ..." goes to stderr and CommandExit{2} is thrown if any failed. Throws urdfsnap::Error
// before running any when `output` (-o) has no {stem}, or two bags have one stem, since their files
// would then overwrite each other.
void AnimateEachBag(const std::vector<std::string>& bags, const std::string& output,
                    const std::function<void(const std::string& bag)>& animate_one);

}  // namespace urdfsnap::cli
