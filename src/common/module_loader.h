// urdfsnap's modules: the parts of urdfsnap that need large libraries only some commands use,
// built as shared objects and opened with dlopen when a command first needs them (the pattern of
// OpenCV's videoio plugins and Mesa's drivers), so that the other commands never load those
// libraries: urdfsnap-meshes.so (mesh files: assimp), urdfsnap-video.so (the video encoders and
// reader: FFmpeg, libwebp) and urdfsnap-serve.so (the live view's server: cpp-httplib with
// OpenSSL and brotli).
//
// A module is looked for in $URDFSNAP_MODULE_DIR when set, then beside the program or shared
// library that holds this code (a build tree), then in lib/urdfsnap/ beside that one's bin/ (an
// installed or unpacked tree, wherever it was moved), then in the install prefix's and the Debian
// package's lib/urdfsnap/. A module and the code loading it must come from one build: each module
// exports one function of its own name, ENTRY(version) (a ModuleEntry), which returns its table of
// functions only when `version` is its own urdfsnap version.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace urdfsnap {

// The folders searched for modules, in order (without duplicates).
std::vector<std::filesystem::path> ModuleFolders();

// Opens module `file_name` ("urdfsnap-video.so") once per process and returns what its function
// `entry` returns for this build's version: the module's table. `what`
// names it in errors ("the video encoders"). Throws urdfsnap::Error "WHAT: ..." when
// the module is found in no folder (naming them), does not load (the loader's reason: a broken
// file, a library it needs missing), or belongs to another build of urdfsnap. Thread-safe.
const void* LoadModuleTable(const std::string& file_name, const char* entry,
                            const std::string& what);

// LoadModuleTable's result as the module's table type.
template <typename Table>
const Table& LoadModule(const std::string& file_name, const char* entry, const std::string& what) {
  return *static_cast<const Table*>(LoadModuleTable(file_name, entry, what));
}

// A module's entry point, and the check it makes.
using ModuleEntry = const void* (*)(const char* version);
// True when `version` (the loader's) is this build's version.
bool IsOwnVersion(const char* version);

}  // namespace urdfsnap
