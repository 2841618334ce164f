// EncodeFrames: RunPipeline with image::Image items.
#include "video/encode_frames.h"

#include "stream/pipeline.h"

namespace urdfsnap::video {

void EncodeFrames(std::int64_t count, const std::function<void(std::int64_t, image::Image&)>& make,
                  FrameEncoder& encoder, stream::ProgressBar* progress, std::size_t depth) {
  stream::RunPipeline<image::Image>(count, depth, make,
                                    [&](std::int64_t k, const image::Image& frame) {
                                      encoder.Write(frame);
                                      if (progress) progress->Update(k + 1);
                                    });
  encoder.Finish();
  if (progress) progress->Finish();
}

}  // namespace urdfsnap::video
