// Resolves the GL function pointers declared in gl_api.h.
#include "gl/gl_api.h"

#include <string>

#include "common/error.h"

namespace urdfsnap::gl {

void LoadGlFunctions(GlProcLookup get_proc) {
#define URDFSNAP_LOAD_GL_FUNCTION(type, name)                                           \
  name = reinterpret_cast<type>(get_proc(#name));                                       \
  if (!name) throw Error(std::string("the OpenGL library does not provide ") + #name);
  URDFSNAP_GL_FUNCTIONS(URDFSNAP_LOAD_GL_FUNCTION)
#undef URDFSNAP_LOAD_GL_FUNCTION
}

}  // namespace urdfsnap::gl
