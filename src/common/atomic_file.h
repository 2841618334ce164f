// Writing a whole file so that readers see either the old file or the complete new one, never a
// partial or empty file: the bytes go to a temporary file beside the target, which is then renamed.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap {

// Writes `bytes` to "<path>.tmp-XXXXXX" (created new, mode 0666 less the umask) and renames it to
// `path`. On any failure the temporary file is removed, an existing file at `path` is left as it
// was, and urdfsnap::Error is thrown as "PATH: cannot write: <errno text>".
void WriteFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace urdfsnap
