// Backend names and the URDFSNAP_GL_BACKEND fallback (CompiledInBackends is in gl_context.cpp,
// beside the factory's table of backends).
#include "gl/backend.h"

#include <cstdlib>

#include "common/error.h"

namespace urdfsnap::gl {

std::string_view BackendName(Backend backend) {
  switch (backend) {
    case Backend::kAuto: return "auto";
    case Backend::kOsMesa: return "osmesa";
    case Backend::kEgl: return "egl";
  }
  return "?";
}

Backend ParseBackend(std::string_view name) {
  for (Backend backend : {Backend::kAuto, Backend::kOsMesa, Backend::kEgl}) {
    if (name == BackendName(backend)) return backend;
  }
  throw Error("unknown GL backend '" + std::string(name) +
              "': expected auto, osmesa or egl (compiled in: " + CompiledInBackendNames() + ")");
}

std::string CompiledInBackendNames() {
  std::string names;
  for (Backend backend : CompiledInBackends()) {
    if (!names.empty()) names += ", ";
    names += BackendName(backend);
  }
  return names;
}

Backend ResolveBackend(std::optional<Backend> requested) {
  if (requested) return *requested;
  const char* value = std::getenv(kBackendVariable);
  if (!value || !*value) return Backend::kAuto;
  try {
    return ParseBackend(value);
  } catch (const Error& e) {
    throw Error(std::string(kBackendVariable) + "=" + value + ": " + e.what());
  }
}

}  // namespace urdfsnap::gl
