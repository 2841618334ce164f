// Resolves the GL function pointers declared in gl_api.h.
#include "gl/internal/gl_api.h"

#include <atomic>
#include <mutex>
#include <string>

#include "common/error.h"

namespace urdfsnap::gl {

bool UseGlFunctionsFrom(GlProcLookup get_proc) {
  // every frame calls this: the common case, the table already filled from get_proc, takes no lock
  static std::atomic<GlProcLookup> filled_from{nullptr};
  static std::mutex mutex;
  if (filled_from.load(std::memory_order_acquire) == get_proc) return false;
  std::lock_guard<std::mutex> lock(mutex);
  if (filled_from.load(std::memory_order_relaxed) == get_proc) return false;
  filled_from.store(nullptr, std::memory_order_relaxed);
#define URDFSNAP_LOAD_GL_FUNCTION(type, name)                                           \
  name = reinterpret_cast<type>(get_proc(#name));                                       \
  if (!name) throw Error(std::string("the OpenGL library does not provide ") + #name);
  URDFSNAP_GL_FUNCTIONS(URDFSNAP_LOAD_GL_FUNCTION)
#undef URDFSNAP_LOAD_GL_FUNCTION
  filled_from.store(get_proc, std::memory_order_release);
  return true;
}

}  // namespace urdfsnap::gl
