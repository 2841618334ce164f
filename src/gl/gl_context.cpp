// The context factory: which backends a request may use, in which order, and what to say when
// none makes a context; the background pre-load and the --version report.
#include "gl/gl_context.h"

#include "gl/internal/gl_api.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/error.h"
#include "gl/internal/gl_backends.h"

namespace urdfsnap::gl {

namespace {

struct BackendEntry {
  Backend backend;
  void (*load)();
  std::unique_ptr<GlContext> (*create)();
};

// the compiled-in backends, in auto's order
const std::vector<BackendEntry>& Entries() {
  static const std::vector<BackendEntry> entries = {
#if URDFSNAP_WITH_OSMESA
      {Backend::kOsMesa, LoadOsMesa, CreateOsMesaContext},
#endif
#if URDFSNAP_WITH_EGL
      {Backend::kEgl, LoadEgl, CreateEglContext},
#endif
  };
  return entries;
}

// The entries `backend` may use, in order. Throws urdfsnap::Error for a backend not compiled in.
std::vector<const BackendEntry*> Candidates(Backend backend) {
  std::vector<const BackendEntry*> candidates;
  for (const BackendEntry& entry : Entries()) {
    if (backend == Backend::kAuto || entry.backend == backend) candidates.push_back(&entry);
  }
  if (candidates.empty()) {
    try {
      CheckCompiledIn(backend);
    } catch (const Error& e) {
      throw Error(std::string("cannot make an OpenGL context: ") + e.what());
    }
  }
  return candidates;
}

}  // namespace

const std::vector<Backend>& CompiledInBackends() {
  static const std::vector<Backend> backends = [] {
    std::vector<Backend> list;
    for (const BackendEntry& entry : Entries()) list.push_back(entry.backend);
    return list;
  }();
  return backends;
}

void CheckCompiledIn(Backend backend) {
  const std::vector<Backend>& compiled_in = CompiledInBackends();
  if (backend == Backend::kAuto || std::find(compiled_in.begin(), compiled_in.end(), backend) != compiled_in.end()) {
    return;
  }
  const char* option = backend == Backend::kOsMesa ? "URDFSNAP_WITH_OSMESA" : "URDFSNAP_WITH_EGL";
  throw Error("GL backend '" + std::string(BackendName(backend)) + "' is not compiled into this urdfsnap (built with " +
              option + "=OFF); compiled in: " + CompiledInBackendNames());
}

std::unique_ptr<GlContext> CreateGlContext(std::optional<Backend> requested, const std::string& asked_by) {
  const Backend backend = ResolveBackend(requested);
  const std::string name(BackendName(backend));
  // who asked: the caller, URDFSNAP_GL_BACKEND or nobody (auto)
  const char* variable = std::getenv(kBackendVariable);
  std::string reason = name;
  if (requested) {
    reason = (asked_by.empty() ? "requested" : asked_by) + " " + name;
  } else if (variable && *variable) {
    reason = std::string(kBackendVariable) + "=" + name;
  }
  std::string failures, skipped;
  for (const BackendEntry* entry : Candidates(backend)) {
    try {
      std::unique_ptr<GlContext> context = entry->create();
      context->reason_ = reason + skipped;
      return context;
    } catch (const Error& e) {
      const std::string entry_name(BackendName(entry->backend));
      failures += (failures.empty() ? "" : "; ") + entry_name + ": " + e.what();
      skipped += (skipped.empty() ? ": " : "; ") + entry_name + " failed: " + e.what();
    }
  }
  throw Error("cannot make an OpenGL context (GL backend " + name + "): " + failures);
}

std::string GlContext::Summary() const {
  return std::string(BackendName(backend())) + " (" + reason_ + "): " + description();
}

std::future<void> StartLoadingGl(std::optional<Backend> requested) {
  return std::async(std::launch::async, [requested] {
    try {
      for (const BackendEntry* entry : Candidates(ResolveBackend(requested))) {
        try {
          entry->load();
          return;
        } catch (const Error&) {
          // auto goes on to the next backend; CreateGlContext tries again and reports it
        }
      }
    } catch (const Error&) {
      // a bad URDFSNAP_GL_BACKEND or a backend not compiled in: CreateGlContext reports it
    }
  });
}

std::string DescribeGlBackends() {
  const std::string text = "GL backends compiled in: " + CompiledInBackendNames() +
                           " (auto takes the first that makes a context)\nGL backend here: ";
  try {
    return text + CreateGlContext(std::nullopt)->Summary();
  } catch (const Error& e) {
    return text + "none: " + e.what();
  }
}

std::string DescribeCurrentContext(const std::string& backend_label) {
  auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("unknown");
  };
  // GL_VERSION is "<major>.<minor>[.<release>][ <vendor's text>]"; Mesa's text starts with
  // "(Core Profile)", which the profile mask says for every vendor
  const std::string version = text(GL_VERSION);
  const size_t space = version.find(' ');
  std::string vendor_text = space == std::string::npos ? "" : version.substr(space + 1);
  const std::string mesa_profile = "(Core Profile) ";
  if (vendor_text.rfind(mesa_profile, 0) == 0) vendor_text.erase(0, mesa_profile.size());
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  return backend_label + ", " + text(GL_RENDERER) + ", OpenGL " + version.substr(0, space) +
         ((profile & GL_CONTEXT_CORE_PROFILE_BIT) ? " core" : "") +
         (vendor_text.empty() ? "" : ", " + vendor_text);
}

}  // namespace urdfsnap::gl
