// GifEncoder: palettegen over every frame while storing them, then paletteuse (Sierra-2-4A error
// diffusion, only the rectangle that changed reprocessed so still areas do not shimmer) into the
// GIF encoder and muxer.
#include "video/internal/gif_encoder.h"

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/number_text.h"
#include "video/internal/ffmpeg_output.h"
#include "video/internal/filter_graph.h"
#include "video/internal/frame_size.h"
#include "video/internal/frame_store.h"

namespace urdfsnap::video {
namespace {

constexpr double kMaxBrowserFps = 50;  // a 2/100 s delay: the shortest browsers honour

// An AVFrame that points at an RGB image's pixels (the filter graph copies what it keeps).
void Wrap(const image::Image& image, std::int64_t pts, AVFrame* frame) {
  frame->format = AV_PIX_FMT_RGB24;
  frame->width = image.width;
  frame->height = image.height;
  frame->data[0] = const_cast<std::uint8_t*>(image.rgb.data());
  frame->linesize[0] = 3 * image.width;
  frame->pts = pts;
}

class GifEncoder final : public FrameEncoder {
 public:
  GifEncoder(const std::string& path, const EncoderSettings& settings)
      : settings_(settings),
        rate_(FrameRate(settings.fps)),
        file_(path),
        store_(settings.width, settings.height, path),
        palette_statistics_({Source(AV_PIX_FMT_RGB24)},
                            "[in0]palettegen=max_colors=256:stats_mode=full[out]", path),
        frame_(av_frame_alloc()) {
    if (!frame_) throw std::bad_alloc();
  }

  void Write(const image::Image& frame) override {
    CheckFrameSize(frame, settings_, file_.path());
    store_.Append(frame);
    av_frame_unref(frame_.get());
    Wrap(frame, store_.count() - 1, frame_.get());
    palette_statistics_.Push(0, frame_.get());
    frame_->data[0] = nullptr;
  }

  void Finish() override {
    if (store_.count() == 0) throw Error(file_.path() + ": an animation without frames");
    // the palette: one 16x16 frame once every frame has been seen
    palette_statistics_.Push(0, nullptr);
    AvPointer<AVFrame> palette(av_frame_alloc());
    if (!palette || !palette_statistics_.Pull(palette.get())) {
      throw Error(file_.path() + ": FFmpeg's palettegen made no palette");
    }
    FilterGraph dither({Source(AV_PIX_FMT_RGB24),
                        FilterGraph::Source{static_cast<AVPixelFormat>(palette->format),
                                            palette->width, palette->height, av_inv_q(rate_)}},
                       "[in0][in1]paletteuse=dither=sierra2_4a:diff_mode=rectangle[out]",
                       file_.path());
    dither.Push(1, palette.get());
    dither.Push(1, nullptr);  // one palette for every frame

    AvOptions codec_options, muxer_options;
    muxer_options.Set("loop", "0");  // play forever, as animations on pages do
    EncodedOutput output(
        file_, "gif", avcodec_find_encoder(AV_CODEC_ID_GIF), rate_,
        [&](AVCodecContext* codec) {
          codec->width = settings_.width;
          codec->height = settings_.height;
          codec->pix_fmt = AV_PIX_FMT_PAL8;
        },
        codec_options, muxer_options);
    const auto encode_ready = [&] {
      while (dither.Pull(frame_.get())) output.Send(frame_.get());
    };
    image::Image stored;
    store_.Rewind();
    for (std::int64_t pts = 0; store_.Next(stored); ++pts) {
      av_frame_unref(frame_.get());
      Wrap(stored, pts, frame_.get());
      dither.Push(0, frame_.get());
      frame_->data[0] = nullptr;
      encode_ready();
    }
    dither.Push(0, nullptr);
    encode_ready();
    output.Finish();
    file_.Commit();
  }

 private:
  FilterGraph::Source Source(AVPixelFormat format) const {
    return {format, settings_.width, settings_.height, av_inv_q(rate_)};
  }

  EncoderSettings settings_;
  AVRational rate_;
  AtomicFile file_;
  FrameStore store_;
  FilterGraph palette_statistics_;
  AvPointer<AVFrame> frame_;
};

}  // namespace

std::unique_ptr<FrameEncoder> OpenGifEncoder(const std::string& path,
                                             const EncoderSettings& settings, Warnings& warnings) {
  if (settings.fps > kMaxBrowserFps) {
    warnings.Add(path + ": GIF frame delays are counted in 1/100 s and browsers show those under " +
                 "2/100 s as 1/10 s, so " + FormatNumber(settings.fps) +
                 " frames/s would play slower; 50 frames/s or less plays as meant");
  }
  return std::make_unique<GifEncoder>(path, settings);
}

}  // namespace urdfsnap::video
