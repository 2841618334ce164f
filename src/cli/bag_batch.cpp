// AnimateEachBag: the outputs checked for {stem} and distinct stems first, then one bag after the
// other, errors printed as main prints them, and the summary.
#include "cli/bag_batch.h"

#include <cstdio>
#include <filesystem>
#include <map>

#include "cli/command.h"
#include "common/error.h"

namespace urdfsnap::cli {

std::string BagStem(const std::string& bag) {
  std::filesystem::path path(bag);
  if (!path.has_filename()) path = path.parent_path();   // a folder given as "run/"
  if (std::filesystem::is_directory(path)) return path.filename().string();
  return path.stem().string();
}

std::string WithStem(std::string pattern, const std::string& stem) {
  const std::string placeholder = kStemPlaceholder;
  for (std::size_t at = 0; (at = pattern.find(placeholder, at)) != std::string::npos; at += stem.size()) {
    pattern.replace(at, placeholder.size(), stem);
  }
  return pattern;
}

void AnimateEachBag(const std::vector<std::string>& bags, const std::string& output,
                    const std::function<void(const std::string& bag)>& animate_one) {
  if (output.find(kStemPlaceholder) == std::string::npos) {
    throw Error("-o '" + output + "': " + std::to_string(bags.size()) + " bags are animated each into its own "
                "file: put {stem} (each bag's name) in it, such as out/{stem}.mp4");
  }
  std::map<std::string, std::string> stems;   // stem → the first bag with it
  for (const std::string& bag : bags) {
    const auto [at, fresh] = stems.emplace(BagStem(bag), bag);
    if (!fresh) {
      throw Error("'" + at->second + "' and '" + bag + "' have the same name '" + at->first + "': their {stem} "
                  "outputs would overwrite each other");
    }
  }
  std::string failed;
  std::size_t failures = 0;
  for (const std::string& bag : bags) {
    try {
      animate_one(bag);
    } catch (const Error& e) {
      std::fprintf(stderr, "urdfsnap: error: %s\n", e.what());
      failed += (failures++ == 0 ? "" : ", ") + bag;
    }
  }
  std::fprintf(stderr, "urdfsnap: animated %zu of %zu bags%s\n", bags.size() - failures, bags.size(),
               failures == 0 ? "" : ("; failed: " + failed).c_str());
  if (failures > 0) throw CommandExit{2};
}

}  // namespace urdfsnap::cli
