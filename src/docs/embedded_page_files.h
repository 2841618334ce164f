// Access to the files the docs page embeds (page.css), compiled into the binary
// (cmake/EmbedFiles.cmake).
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap::docs {

// The text of src/docs/<name> (e.g. "page.css"); throws urdfsnap::Error for an unknown name.
std::string_view EmbeddedPageFile(std::string_view name);

}  // namespace urdfsnap::docs
