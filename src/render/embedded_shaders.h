// Access to the GLSL sources of shaders/, compiled into the binary (cmake/EmbedShaders.cmake).
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap::render {

// The source of shaders/<name> (e.g. "lit.vert"); throws urdfsnap::Error for an unknown name.
std::string_view EmbeddedShader(std::string_view name);

}  // namespace urdfsnap::render
