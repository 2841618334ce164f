// --gl-backend and --verbose, on every command that renders (render, animate, docs, serve,
// snapshot check/update): which GL backend makes the contexts, beating URDFSNAP_GL_BACKEND, and a
// line on stderr saying which backend was taken and why, printed when the first context is made.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "gl/backend.h"

namespace urdfsnap::cli {

struct GlOptions {
  std::string backend;   // --gl-backend NAME, checked by gl::ParseBackend and gl::CheckCompiledIn; "" when not given
  bool verbose = false;  // --verbose

  // Adds --gl-backend and --verbose to `command`; `verbose_also` ends --verbose's help with what
  // else the command says under it (", and ...").
  void AddOptions(CLI::App& command, const std::string& verbose_also = "");

  // What the typed core is given: the backend (nullopt when --gl-backend is not given) and, under
  // --verbose, "urdfsnap: GL backend egl (--gl-backend egl): EGL (surfaceless), ..." on stderr for
  // the first context made (and again only for a context that differs from it).
  gl::BackendChoice Choice() const;
};

}  // namespace urdfsnap::cli
