// The PNG sequence output: each frame encoded exactly as `urdfsnap render` writes a PNG
// (image::EncodePng), into numbered files.
#pragma once

#include <memory>
#include <string>

#include "video/frame_encoder.h"

namespace urdfsnap::video {

std::unique_ptr<FrameEncoder> OpenPngSequenceEncoder(const std::string& pattern,
                                                     const EncoderSettings& settings);

}  // namespace urdfsnap::video
