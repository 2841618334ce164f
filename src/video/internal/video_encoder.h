// The MP4 (H.264 through libx264) and WebM (VP9 through libvpx) outputs, both through FFmpeg's
// libavcodec and libavformat, with RGB frames converted to BT.709 yuv420p by libswscale.
#pragma once

#include <memory>
#include <string>

#include "video/frame_encoder.h"

namespace urdfsnap::video {

// `format` is kMp4 or kWebm.
std::unique_ptr<FrameEncoder> OpenVideoEncoder(const std::string& path, OutputFormat format,
                                               const EncoderSettings& settings);

}  // namespace urdfsnap::video
