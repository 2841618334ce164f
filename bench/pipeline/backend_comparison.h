// EGL against OSMesa in one run of the pipeline benchmark: each compiled-in backend measured in a
// fresh process of this benchmark (so each pays its own library load), side by side.
#pragma once

#include <string>

namespace urdfsnap::bench {

// The option that makes the benchmark measure one backend in its own process and print its
// figures as one line (MeasureBackend).
inline constexpr char kMeasureBackendOption[] = "--measure-backend";

// In this fresh process, for `backend` ("osmesa", "egl"): the first context (library load
// included), later contexts, and per frame the draw of `model` (mrm) at 640x480 with 4x MSAA
// with read-back; writes them in seconds, then the context's description, as one line to
// `figures`. Returns the process's exit status (2 when no context can be made).
int MeasureBackend(const std::string& backend, const std::string& model, const std::string& figures);

// Prints the table: the figures above from `self --measure-backend NAME MODEL FILE` for each
// compiled-in backend, and the whole `binary render MODEL` process with URDFSNAP_GL_BACKEND=NAME.
void PrintBackendComparison(const std::string& self, const std::string& binary, const std::string& model);

}  // namespace urdfsnap::bench
