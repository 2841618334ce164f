// VideoEncoder: one yuv420p frame reused for every input, the codec's settings per format.
#include "video/internal/video_encoder.h"

extern "C" {
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "common/atomic_file.h"
#include "common/error.h"
#include "video/internal/ffmpeg_output.h"
#include "video/internal/frame_size.h"

namespace urdfsnap::video {
namespace {

// Both formats play in every browser as 4:2:0 with the BT.709 matrix in limited range, the
// colours tagged so that players convert back to the same RGB.
void ConfigureColour(AVCodecContext* codec) {
  codec->pix_fmt = AV_PIX_FMT_YUV420P;
  codec->color_range = AVCOL_RANGE_MPEG;
  codec->colorspace = AVCOL_SPC_BT709;
  codec->color_primaries = AVCOL_PRI_BT709;
  codec->color_trc = AVCOL_TRC_BT709;
}

struct SwsFreer {
  void operator()(SwsContext* context) const { sws_freeContext(context); }
};

class VideoEncoder final : public FrameEncoder {
 public:
  VideoEncoder(const std::string& path, OutputFormat format, const EncoderSettings& settings)
      : settings_(settings), file_(path) {
    TakeOverFfmpegLog();
    AvOptions codec_options, muxer_options;
    const AVCodec* codec = nullptr;
    const char* muxer = nullptr;
    if (format == OutputFormat::kMp4) {
      // x264's veryfast preset at CRF 20: about 400 frames/s at 640x480 on one core with sharp
      // robot edges (bench/video); faststart puts the index first so browsers play while loading
      codec = avcodec_find_encoder_by_name("libx264");
      muxer = "mp4";
      codec_options.Set("preset", "veryfast").Set("crf", "20");
      muxer_options.Set("movflags", "+faststart");
    } else {
      // VP9 in constant quality (CRF 32 with no bitrate target), libvpx's realtime speed 8 with
      // row multithreading: the only VP9 setting fast enough to keep up with rendering
      codec = avcodec_find_encoder_by_name("libvpx-vp9");
      muxer = "webm";
      codec_options.Set("crf", "32")
          .Set("deadline", "realtime")
          .Set("cpu-used", "8")
          .Set("row-mt", "1");
    }
    const int width = settings.width, height = settings.height;
    output_ = std::make_unique<EncodedOutput>(
        file_, muxer, codec, FrameRate(settings.fps),
        [&](AVCodecContext* context) {
          context->width = width;
          context->height = height;
          context->bit_rate = 0;
          context->thread_count = 0;  // the encoder's choice, by the machine's cores
          ConfigureColour(context);
        },
        codec_options, muxer_options);

    yuv_ = MakeFrame(AV_PIX_FMT_YUV420P, width, height, path);
    scaler_.reset(sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P,
                                 SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr,
                                 nullptr, nullptr));
    if (!scaler_) throw Error(path + ": cannot convert RGB to yuv420p");
    // full-range RGB in, limited-range BT.709 out, matching the tags above
    sws_setColorspaceDetails(scaler_.get(), sws_getCoefficients(SWS_CS_ITU709), 1,
                             sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);
  }

  void Write(const image::Image& frame) override {
    CheckFrameSize(frame, settings_, file_.path());
    CheckAv(av_frame_make_writable(yuv_.get()), file_.path(), "cannot encode");
    const std::uint8_t* rgb[1] = {frame.rgb.data()};
    const int rgb_stride[1] = {3 * frame.width};
    sws_scale(scaler_.get(), rgb, rgb_stride, 0, frame.height, yuv_->data, yuv_->linesize);
    yuv_->pts = frames_++;
    output_->Send(yuv_.get());
  }

  void Finish() override {
    output_->Finish();
    file_.Commit();
  }

 private:
  EncoderSettings settings_;
  AtomicFile file_;  // declared first: removed only after the muxer has closed it
  std::unique_ptr<EncodedOutput> output_;
  AvPointer<AVFrame> yuv_;
  std::unique_ptr<SwsContext, SwsFreer> scaler_;
  std::int64_t frames_ = 0;
};

}  // namespace

std::unique_ptr<FrameEncoder> OpenVideoEncoder(const std::string& path, OutputFormat format,
                                               const EncoderSettings& settings) {
  if (format == OutputFormat::kMp4 && (settings.width % 2 != 0 || settings.height % 2 != 0)) {
    throw Error(path + ": H.264 in 4:2:0 needs an even width and height; " +
                std::to_string(settings.width) + "x" + std::to_string(settings.height) + " is odd");
  }
  return std::make_unique<VideoEncoder>(path, format, settings);
}

}  // namespace urdfsnap::video
