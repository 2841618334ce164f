// GlOptions: the option's check (the factory's own messages for a name it does not know or a
// backend this build lacks), its help, and the --verbose line.
#include "cli/gl_options.h"

#include <cstdio>
#include <memory>

#include "common/error.h"

namespace urdfsnap::cli {

namespace {

constexpr char kOption[] = "--gl-backend";

}  // namespace

void GlOptions::AddOptions(CLI::App& command, const std::string& verbose_also) {
  command
      .add_option(kOption, backend,
                  "off-screen OpenGL to render with: auto (OSMesa when it loads, else EGL), osmesa or "
                  "egl (a GPU through EGL's device platform, else Mesa's llvmpipe); compiled in: " +
                      gl::CompiledInBackendNames() + " (default: $" + gl::kBackendVariable +
                      ", else auto)")
      ->type_name("NAME")
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            try {
              gl::CheckCompiledIn(gl::ParseBackend(name));
              return "";
            } catch (const Error& e) {
              return e.what();
            }
          },
          ""));
  command.add_flag("--verbose", verbose,
                   "say on stderr which GL backend was taken and why, with its renderer and OpenGL "
                   "version" + verbose_also + " (default: off)");
}

gl::BackendChoice GlOptions::Choice() const {
  gl::BackendChoice choice;
  if (!backend.empty()) {
    choice.backend = gl::ParseBackend(backend);
    choice.asked_by = kOption;
  }
  if (verbose) {
    choice.on_context = [printed = std::make_shared<std::string>()](const std::string& summary) {
      if (summary == *printed) return;
      *printed = summary;
      std::fprintf(stderr, "urdfsnap: GL backend %s\n", summary.c_str());
      std::fflush(stderr);
    };
  }
  return choice;
}

}  // namespace urdfsnap::cli
