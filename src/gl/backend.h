// The off-screen OpenGL backends by name: which exist, which this build has (the CMake options
// URDFSNAP_WITH_OSMESA and URDFSNAP_WITH_EGL), and which one a command uses when none is asked
// for (URDFSNAP_GL_BACKEND, else auto). No GL here: the command line and the typed core include it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace urdfsnap::gl {

enum class Backend {
  kAuto,    // OSMesa when it loads and makes a context, else EGL
  kOsMesa,  // Mesa's off-screen library (libOSMesa, llvmpipe); gone from Mesa 25.1 on
  kEgl,     // libEGL: a GPU through EGL's device platform, else Mesa's surfaceless llvmpipe
};

// The environment variable read when no backend is requested.
inline constexpr char kBackendVariable[] = "URDFSNAP_GL_BACKEND";

// "auto", "osmesa" or "egl".
std::string_view BackendName(Backend backend);

// The backend named `name` ("auto", "osmesa", "egl"). Throws urdfsnap::Error naming the valid
// names and those compiled in. A backend that is not compiled in parses; the factory refuses it.
Backend ParseBackend(std::string_view name);

// The concrete backends this build has, in auto's order of preference (OSMesa first).
const std::vector<Backend>& CompiledInBackends();

// "osmesa, egl": the compiled-in backends' names, for messages and help texts.
std::string CompiledInBackendNames();

// `requested` when given, else the value of URDFSNAP_GL_BACKEND when set and not empty, else
// kAuto. Throws urdfsnap::Error naming the variable when its value is not a backend's name.
Backend ResolveBackend(std::optional<Backend> requested);

}  // namespace urdfsnap::gl
