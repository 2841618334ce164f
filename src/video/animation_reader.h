// Reading an animation back frame by frame, as 8-bit RGB with the time each frame ends: GIF, MP4
// and WebM through FFmpeg's libavformat/libavcodec (converted by libswscale), animated WebP through
// libwebp's animation decoder (FFmpeg 5 reads no animated WebP), inside the video module. For
// comparing a committed animation with a fresh one (`docs --check`), one frame in memory at a time.
#pragma once

#include <memory>
#include <string>

#include "image/image.h"

namespace urdfsnap::video {

class AnimationReader {
 public:
  virtual ~AnimationReader() = default;

  // Fills `frame` with the next frame and `end_ms` with the time it stops showing (milliseconds
  // from the start); false after the last frame. Throws urdfsnap::Error for data that does not
  // decode.
  virtual bool Next(image::Image& frame, double& end_ms) = 0;
};

// Opens the animation at `path` by its extension (.gif, .webp, .mp4, .webm), through the video
// module (codec_module.h), loaded on first use. Throws urdfsnap::Error naming the path when it
// cannot be read or is not such an animation, or when the module cannot be loaded.
std::unique_ptr<AnimationReader> OpenAnimationReader(const std::string& path);

// What OpenAnimationReader calls inside urdfsnap-video.so.
std::unique_ptr<AnimationReader> OpenAnimationFile(const std::string& path);

}  // namespace urdfsnap::video
