// Fuzz target: an animation read back frame by frame as `docs --check` reads committed GIF and WebP
// files (video::AnimationReader: FFmpeg's GIF demuxer and decoder, libwebp's animation decoder).
// The first byte picks the format (even: GIF, odd: WebP). Only urdfsnap::Error may come out.
#include <cstddef>
#include <cstdint>

#include "common/error.h"
#include "fuzz_work_dir.h"
#include "video/animation_reader.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  urdfsnap::fuzz::EnterFreshWorkDir();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace urdfsnap;
  if (size < 1) return 0;
  const std::string path = fuzz::WriteInput(data[0] % 2 ? "animation.webp" : "animation.gif", data + 1, size - 1);
  try {
    const auto reader = video::OpenAnimationReader(path);
    image::Image frame;
    double end_ms = 0;
    // a bounded number of frames: a long animation is no finding
    for (int k = 0; k < 256 && reader->Next(frame, end_ms); ++k) {
    }
  } catch (const Error&) {
  }
  return 0;
}
