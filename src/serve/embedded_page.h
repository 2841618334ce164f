// Access to the live view's page (src/serve/page/), compiled into the binary
// (cmake/EmbedFiles.cmake), so that the server reads no file to serve it.
#pragma once

#include <string_view>

namespace urdfsnap::serve {

// The content of page/<name> ("index.html", "page.js", "page.css", "favicon.svg"); throws urdfsnap::Error for
// an unknown name.
std::string_view EmbeddedPageFile(std::string_view name);

}  // namespace urdfsnap::serve
