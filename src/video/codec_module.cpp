// Codecs: LoadModule of urdfsnap-video.so, and OpenAnimationReader through it.
#include "video/internal/codec_module.h"

#include "common/error.h"
#include "common/module_loader.h"

namespace urdfsnap::video {

const CodecModule& Codecs(const std::string& path) {
  try {
    return LoadModule<CodecModule>(URDFSNAP_VIDEO_MODULE, kCodecModuleEntry,
                                   "the MP4, WebM, GIF and WebP codecs (FFmpeg, libwebp)");
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
}

std::unique_ptr<AnimationReader> OpenAnimationReader(const std::string& path) {
  return Codecs(path).open_animation_file(path);
}

}  // namespace urdfsnap::video
