// OutputFormatOf: the extension decides; OutputFormatName for messages.
#include "video/frame_encoder.h"

#include "common/error.h"
#include "common/file_extension.h"
#include "video/frame_pattern.h"

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

}  // namespace urdfsnap::video
