// The GIF output: one palette of 255 colours (and a transparent entry for unchanged pixels) for the
// whole animation, made by FFmpeg's palettegen from the colours of every frame, then every frame
// dithered to it by paletteuse and encoded by FFmpeg's GIF encoder. Both passes stream: in the
// first the frames go to the palette statistics and, compressed, to an unnamed temporary file
// (FrameStore); the second reads them back one by one. Memory stays that of a few frames; the
// temporary file takes a small fraction of the raw frames (15 KiB for a 900 KiB 640x480 frame of
// bench/video's robot-like frames), in $TMPDIR.
#pragma once

#include <memory>
#include <string>

#include "common/warnings.h"
#include "video/frame_encoder.h"

namespace urdfsnap::video {

// Warns when `settings.fps` is above 50: GIF frame delays are counted in 1/100 s and browsers show
// delays under 2/100 s as 1/10 s.
std::unique_ptr<FrameEncoder> OpenGifEncoder(const std::string& path,
                                             const EncoderSettings& settings, Warnings& warnings);

}  // namespace urdfsnap::video
