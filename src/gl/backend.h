// The off-screen OpenGL backends by name: which exist, which this build has (the CMake options
// URDFSNAP_WITH_OSMESA and URDFSNAP_WITH_EGL), and which one a command uses when none is asked
// for (URDFSNAP_GL_BACKEND, else auto). No GL here: the command line and the typed core include it.
#pragma once

#include <functional>
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

// What a caller of the typed core asks of the backend factory for the GL contexts it makes (one per
// gl::SceneRenderer; RenderSession, animate's and docs' renderers and the live view's pass it on).
struct BackendChoice {
  BackendChoice() = default;
  // SceneRenderer(4, {Backend::kEgl}): that backend, nobody to tell
  BackendChoice(std::optional<Backend> backend) : backend(backend) {}  // NOLINT(google-explicit-constructor)

  // the backend asked for; nullopt: URDFSNAP_GL_BACKEND when set, else auto
  std::optional<Backend> backend;
  // who asked for `backend`, for the reason a context gives (GlContext::reason), e.g.
  // "--gl-backend"; empty: "requested"
  std::string asked_by;
  // called with GlContext::Summary() of each context made, as soon as it is made (--verbose)
  std::function<void(const std::string& summary)> on_context;
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

// Throws urdfsnap::Error naming the compiled-in backends when `backend` is kOsMesa or kEgl and
// this build lacks it ("GL backend 'osmesa' is not compiled into this urdfsnap (built with
// URDFSNAP_WITH_OSMESA=OFF); compiled in: egl").
void CheckCompiledIn(Backend backend);

// "osmesa, egl": the compiled-in backends' names, for messages and help texts.
std::string CompiledInBackendNames();

// `requested` when given, else the value of URDFSNAP_GL_BACKEND when set and not empty, else
// kAuto. Throws urdfsnap::Error naming the variable when its value is not a backend's name.
Backend ResolveBackend(std::optional<Backend> requested);

}  // namespace urdfsnap::gl
