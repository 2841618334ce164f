// An animation from its frames: each frame made on the calling thread (where the GL context is)
// while the previous ones are encoded on a worker thread (stream::RunPipeline), with a progress bar
// as frames finish. Memory holds a few frames, however many there are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "image/image.h"
#include "stream/progress_bar.h"
#include "video/frame_encoder.h"

namespace urdfsnap::video {

// Calls make(k, frame) for k = 0 .. count - 1 (filling `frame`, whose buffer is reused) and writes
// each frame to `encoder` in order, then finishes it. `progress`, if given, is updated as frames
// are encoded and finished at the end. At most `depth` made frames wait for the encoder. The first
// error from either side stops both and is rethrown; the encoder is then left unfinished, so its
// destruction removes what it wrote.
void EncodeFrames(std::int64_t count, const std::function<void(std::int64_t, image::Image&)>& make,
                  FrameEncoder& encoder, stream::ProgressBar* progress = nullptr,
                  std::size_t depth = 4);

}  // namespace urdfsnap::video
