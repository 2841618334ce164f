// OpenFrameEncoder: the format from OutputFormatOf, the settings checked once, then the encoder: PNG
// sequences here, the other formats from the video module (codec_module.h).
#include "video/open_frame_encoder.h"

#include <cmath>

#include "common/error.h"
#include "video/internal/codec_module.h"
#include "video/internal/png_sequence_encoder.h"

namespace urdfsnap::video {

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
