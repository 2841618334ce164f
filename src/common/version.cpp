// Version: the one place the build's version string is compiled in (URDFSNAP_VERSION from CMake).
#include "common/version.h"

namespace urdfsnap {

const char* Version() { return URDFSNAP_VERSION; }

}  // namespace urdfsnap
