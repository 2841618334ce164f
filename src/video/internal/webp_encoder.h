// The animated WebP output through libwebp's animation encoder (WebPAnimEncoder: lossy frames,
// only the changed rectangle of each, identical frames merged into longer ones). That encoder
// keeps a whole animation in memory until it is assembled, so frames are encoded in segments of a
// few seconds; each segment's frames are taken out of its assembled file (WebPDemux) and appended
// to one WebP container written here, whose sizes are filled in at the end. Memory is one
// segment's, whatever the animation's length.
#pragma once

#include <memory>
#include <string>

#include "video/frame_encoder.h"

namespace urdfsnap::video {

// Throws Error for a side over WebP's 16383 pixels.
std::unique_ptr<FrameEncoder> OpenWebpEncoder(const std::string& path,
                                              const EncoderSettings& settings);

}  // namespace urdfsnap::video
