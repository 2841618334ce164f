// Animations for docs pages through the encoders of `urdfsnap animate` (video::OpenFrameEncoder):
// frames rendered on this thread while the previous ones are encoded (video::EncodeFrames).
#include "docs/animation_output.h"

#include "common/error.h"
#include "common/warnings.h"
#include "video/encode_frames.h"
#include "video/open_frame_encoder.h"

namespace urdfsnap::docs {

std::vector<std::string> AnimationExtensions() { return {".gif", ".webp"}; }

void WriteAnimation(const std::string& path, PictureSize size, double fps, int count,
                    const std::function<void(int, image::Image&)>& render) {
  // docs pages use frame rates GIF can hold, so the encoder has no advice to give here
  Warnings ignored;
  const auto encoder = video::OpenFrameEncoder(path, {size.width, size.height, fps}, ignored);
  video::EncodeFrames(count, [&](std::int64_t k, image::Image& frame) { render(static_cast<int>(k), frame); },
                      *encoder);
}

}  // namespace urdfsnap::docs
