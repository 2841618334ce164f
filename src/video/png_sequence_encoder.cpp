// PngSequenceEncoder: image::EncodePng into NumberedFiles.
#include "video/internal/png_sequence_encoder.h"

#include "image/png_writer.h"
#include "video/numbered_files.h"
#include "video/internal/frame_size.h"

namespace urdfsnap::video {
namespace {

class PngSequenceEncoder final : public FrameEncoder {
 public:
  PngSequenceEncoder(const std::string& pattern, const EncoderSettings& settings)
      : settings_(settings), files_(pattern, settings.first_frame, settings.staging) {}

  void Write(const image::Image& frame) override {
    CheckFrameSize(frame, settings_, files_.pattern().pattern());
    const std::vector<std::uint8_t> png = image::EncodePng(frame);
    files_.Write({reinterpret_cast<const char*>(png.data()), png.size()});
  }

  void Finish() override { files_.Finish(); }

 private:
  EncoderSettings settings_;
  NumberedFiles files_;
};

}  // namespace

std::unique_ptr<FrameEncoder> OpenPngSequenceEncoder(const std::string& pattern,
                                                     const EncoderSettings& settings) {
  return std::make_unique<PngSequenceEncoder>(pattern, settings);
}

}  // namespace urdfsnap::video
