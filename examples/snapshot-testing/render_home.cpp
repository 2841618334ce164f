// Renders the pan-tilt head's home view through urdfsnap's C++ library, with the same request a
// snapshot suite case or `urdfsnap render MODEL --size 480x360 --fit` makes.
// usage: render_home MODEL OUTPUT.png
#include <cstdio>
#include <string>

#include "common/error.h"
#include "image/png_writer.h"
#include "request/render_session.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: render_home MODEL OUTPUT.png\n");
    return 2;
  }
  urdfsnap::request::RenderRequest request;
  request.model.path = argv[1];
  request.size = "480x360";
  request.fit = true;
  try {
    urdfsnap::Warnings warnings;
    urdfsnap::request::RenderSession session;
    const urdfsnap::image::Image image =
        session.Render(request, urdfsnap::request::CommandLineLabel, warnings).frame.colour;
    for (const std::string& message : warnings.messages()) std::fprintf(stderr, "warning: %s\n", message.c_str());
    urdfsnap::image::WritePng(image, argv[2]);
  } catch (const urdfsnap::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
