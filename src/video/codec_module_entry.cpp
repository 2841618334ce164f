// urdfsnap-video.so's entry point: its table of encoders and the reader, for its own build only.
#include "common/module_loader.h"
#include "video/internal/codec_module.h"
#include "video/internal/gif_encoder.h"
#include "video/internal/video_encoder.h"
#include "video/internal/webp_encoder.h"

// kCodecModuleEntry
extern "C" __attribute__((visibility("default"))) const void* urdfsnap_video_module(
    const char* version) {
  using namespace urdfsnap::video;
  static const CodecModule table{&OpenVideoEncoder, &OpenGifEncoder, &OpenWebpEncoder,
                                 &OpenAnimationFile};
  return urdfsnap::IsOwnVersion(version) ? &table : nullptr;
}
