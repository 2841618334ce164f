// Access to the GLSL sources of shaders/, compiled into the binary (cmake/EmbedFiles.cmake).
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap::gl {

// The source of shaders/<name> (e.g. "lit.vert"); throws urdfsnap::Error for an unknown name.
std::string_view EmbeddedShader(std::string_view name);

}  // namespace urdfsnap::gl
