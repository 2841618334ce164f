// Animations for docs pages: none until the encoders of `urdfsnap animate` are in the build.
#include "docs/animation_output.h"

#include "common/error.h"

namespace urdfsnap::docs {

std::vector<std::string> AnimationExtensions() { return {}; }

void WriteAnimation(const std::string& path, PictureSize, double, int, const std::function<void(int, image::Image&)>&) {
  throw Error(path + ": this build of urdfsnap writes no animations");
}

}  // namespace urdfsnap::docs
