// The video module, urdfsnap-video.so (common/module_loader.h): the outputs and the reader that
// need FFmpeg or libwebp, loaded when an animation is first written or read in one of those
// formats, so that nothing else (PNG sequences included) loads those libraries. Its table holds
// the functions the format dispatch (frame_encoder.cpp) and OpenAnimationReader call.
#pragma once

#include <memory>
#include <string>

#include "common/warnings.h"
#include "video/animation_reader.h"
#include "video/frame_encoder.h"

namespace urdfsnap::video {

// the module's entry point (codec_module_entry.cpp)
inline constexpr char kCodecModuleEntry[] = "urdfsnap_video_module";

struct CodecModule {
  // video_encoder.h, gif_encoder.h, webp_encoder.h and animation_reader.h inside the module
  std::unique_ptr<FrameEncoder> (*open_video_encoder)(const std::string& path, OutputFormat format,
                                                      const EncoderSettings& settings);
  std::unique_ptr<FrameEncoder> (*open_gif_encoder)(const std::string& path,
                                                    const EncoderSettings& settings,
                                                    Warnings& warnings);
  std::unique_ptr<FrameEncoder> (*open_webp_encoder)(const std::string& path,
                                                     const EncoderSettings& settings);
  std::unique_ptr<AnimationReader> (*open_animation_file)(const std::string& path);
};

// The module's table, loaded on the first call. Throws urdfsnap::Error "PATH: the video encoders
// ...: why" when the module is missing, broken or from another build; `path` is the file the
// caller was about to write or read.
const CodecModule& Codecs(const std::string& path);

}  // namespace urdfsnap::video
