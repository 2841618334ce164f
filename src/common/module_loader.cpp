// ModuleFolders and LoadModuleTable: where this code was loaded from (dladdr1), the folders beside
// it, and one SharedLibrary per module kept for the process.
#include "common/module_loader.h"

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <system_error>

#include "common/error.h"
#include "common/shared_library.h"
#include "common/version.h"

namespace urdfsnap {

namespace {

// The folder of the program or shared library this function is part of: the program's own path
// comes from /proc/self/exe (the loader names it ""), a library's from its link map.
std::filesystem::path OwnFolder() {
  Dl_info info;
  link_map* map = nullptr;
  std::error_code error;
  std::filesystem::path file;
  if (dladdr1(reinterpret_cast<void*>(&OwnFolder), &info, reinterpret_cast<void**>(&map),
              RTLD_DL_LINKMAP) != 0 &&
      map != nullptr && map->l_name != nullptr && map->l_name[0] != '\0') {
    file = map->l_name;
  } else {
    file = "/proc/self/exe";
  }
  const std::filesystem::path resolved = std::filesystem::canonical(file, error);
  return error ? std::filesystem::path() : resolved.parent_path();
}

}  // namespace

std::vector<std::filesystem::path> ModuleFolders() {
  std::vector<std::filesystem::path> folders;
  auto add = [&folders](const std::filesystem::path& folder) {
    if (folder.empty()) return;
    const std::filesystem::path normal = folder.lexically_normal();
    for (const auto& known : folders) {
      if (known == normal) return;
    }
    folders.push_back(normal);
  };
  if (const char* chosen = std::getenv("URDFSNAP_MODULE_DIR"); chosen && *chosen) add(chosen);
  const std::filesystem::path own = OwnFolder();
  add(own);
  if (!own.empty()) add(own / URDFSNAP_MODULE_DIR_FROM_BIN);
  add(URDFSNAP_MODULE_INSTALL_DIR);
  add(URDFSNAP_MODULE_PACKAGE_DIR);
  return folders;
}

bool IsOwnVersion(const char* version) { return version && std::strcmp(version, Version()) == 0; }

const void* LoadModuleTable(const std::string& file_name, const char* entry,
                            const std::string& what) {
  static std::mutex mutex;
  static std::map<std::string, const void*> tables;
  const std::lock_guard lock(mutex);
  if (const auto known = tables.find(file_name); known != tables.end()) return known->second;

  constexpr const char* kRemedy = "it is part of urdfsnap: reinstall or rebuild it";
  std::filesystem::path path;
  std::string looked;
  for (const auto& folder : ModuleFolders()) {
    std::error_code error;
    if (std::filesystem::is_regular_file(folder / file_name, error)) {
      path = folder / file_name;
      break;
    }
    looked += (looked.empty() ? "" : ", ") + folder.string();
  }
  if (path.empty()) {
    throw Error(what + ": " + file_name + " is in none of " + looked + " (" + kRemedy +
                ", or set URDFSNAP_MODULE_DIR)");
  }
  try {
    // never closed (SharedLibrary), so the table stays valid for the process
    const SharedLibrary library(path.string(), kRemedy);
    const void* table = library.Get<ModuleEntry>(entry)(Version());
    if (!table) {
      throw Error(path.string() + " is from another build of urdfsnap than this " + Version() +
                  " (" + kRemedy + ")");
    }
    return tables[file_name] = table;
  } catch (const Error& e) {
    throw Error(what + ": " + e.what());
  }
}

}  // namespace urdfsnap
