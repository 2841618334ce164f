// urdfsnap's version, from project(VERSION) in CMakeLists.txt: printed by --version, written into
// results files (which merge only with results of the same version) and the Debian package's name.
#pragma once

namespace urdfsnap {

// "0.1.0".
const char* Version();

}  // namespace urdfsnap
