// Opening the encoder an output's extension names (video/frame_encoder.h): settings checked once
// here, PNG sequences written by urdfsnap_video itself, the other formats by the video module
// (codec_module.h), loaded when first needed.
#pragma once

#include <memory>
#include <string>

#include "common/warnings.h"
#include "video/frame_encoder.h"

namespace urdfsnap::video {

// Opens the encoder for `path` (see OutputFormatOf), creating its temporary output at once so that
// an unwritable place is reported before any frame is made. Throws Error for an unknown format, a
// size the format cannot hold (odd sides for MP4's 4:2:0 chroma, WebP's 16383 pixels), a bad
// frame rate, a video starting past frame 0, or an output that cannot be written. Advice that is no error (GIF frame delays
// browsers do not honour) goes to `warnings`.
std::unique_ptr<FrameEncoder> OpenFrameEncoder(const std::string& path,
                                               const EncoderSettings& settings, Warnings& warnings);

}  // namespace urdfsnap::video
