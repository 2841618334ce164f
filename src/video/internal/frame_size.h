// The check every encoder makes on each frame: the size it was opened with, consistent pixels.
#pragma once

#include <string>

#include "common/error.h"
#include "image/image.h"
#include "video/frame_encoder.h"

namespace urdfsnap::video {

// Throws Error "OUTPUT: ..." unless `frame` is a consistent image of the settings' size.
inline void CheckFrameSize(const image::Image& frame, const EncoderSettings& settings,
                           const std::string& output) {
  image::CheckImage(frame, "frame for " + output);
  if (frame.width != settings.width || frame.height != settings.height) {
    throw Error(output + ": a frame of " + image::SizeText(frame) + " in an animation of " +
                std::to_string(settings.width) + "x" + std::to_string(settings.height));
  }
}

}  // namespace urdfsnap::video
