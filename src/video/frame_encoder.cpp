// OutputFormatOf and OpenFrameEncoder: the extension decides, settings are checked once here; PNG
// sequences are written here, the other formats by the video module (codec_module.h).
#include "video/frame_encoder.h"

#include <cmath>
#include <filesystem>

#include "common/error.h"
#include "common/file_extension.h"
#include "video/codec_module.h"
#include "video/frame_pattern.h"
#include "video/png_sequence_encoder.h"

namespace urdfsnap::video {
OutputFormat OutputFormatOf(const std::string& path) {
  const std::string extension = LowerCaseExtension(path);
  if (FramePattern::IsPattern(path)) {
    if (extension == ".png") return OutputFormat::kPngSequence;
    throw Error(path + ": a numbered frame sequence is written as PNG files (frames/%05d.png)");
  }
  if (extension == ".mp4") return OutputFormat::kMp4;
  if (extension == ".webm") return OutputFormat::kWebm;
  if (extension == ".gif") return OutputFormat::kGif;
  if (extension == ".webp") return OutputFormat::kWebp;
  throw Error(path + ": unknown animation format '" + extension +
              "'; urdfsnap writes .mp4, .webm, .gif, .webp, or PNG frames named by a pattern "
              "such as frames/%05d.png");
}

FormatDefaults DefaultsFor(OutputFormat format) {
  if (format == OutputFormat::kGif) return {15, "480x360"};
  return {30, "640x480"};
}

const char* OutputFormatName(OutputFormat format) {
  switch (format) {
    case OutputFormat::kMp4:
      return "MP4 (H.264)";
    case OutputFormat::kWebm:
      return "WebM (VP9)";
    case OutputFormat::kGif:
      return "GIF";
    case OutputFormat::kWebp:
      return "animated WebP";
    case OutputFormat::kPngSequence:
      return "PNG sequence";
  }
  return "";
}

std::unique_ptr<FrameEncoder> OpenFrameEncoder(const std::string& path,
                                               const EncoderSettings& settings,
                                               Warnings& warnings) {
  const OutputFormat format = OutputFormatOf(path);
  if (settings.width < 1 || settings.height < 1 || settings.width > image::kMaxImageSide ||
      settings.height > image::kMaxImageSide) {
    throw Error(path + ": cannot make an animation of " + std::to_string(settings.width) + "x" +
                std::to_string(settings.height) + " pixels (each side 1 to " +
                std::to_string(image::kMaxImageSide) + ")");
  }
  if (!std::isfinite(settings.fps) || settings.fps <= 0) {
    throw Error(path + ": the frame rate must be a positive number of frames per second");
  }
  if (settings.first_frame != 0 && format != OutputFormat::kPngSequence) {
    throw Error(path + ": " + OutputFormatName(format) + " is one file of the whole animation; only a "
                "frame sequence (such as frames/%05d.png) can start at frame " +
                std::to_string(settings.first_frame));
  }
  switch (format) {
    case OutputFormat::kMp4:
    case OutputFormat::kWebm:
      return Codecs(path).open_video_encoder(path, format, settings);
    case OutputFormat::kGif:
      return Codecs(path).open_gif_encoder(path, settings, warnings);
    case OutputFormat::kWebp:
      return Codecs(path).open_webp_encoder(path, settings);
    case OutputFormat::kPngSequence:
      return OpenPngSequenceEncoder(path, settings);
  }
  return nullptr;
}

}  // namespace urdfsnap::video
