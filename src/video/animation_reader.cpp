// OpenAnimationFile (in urdfsnap-video.so): a libwebp WebPAnimDecoder over the file's bytes for
// WebP; libavformat's demuxer, libavcodec's decoder and libswscale's RGB conversion for the rest.
#include "video/animation_reader.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}
#include <webp/demux.h>

#include <cctype>
#include <filesystem>

#include "common/error.h"
#include "common/file_reading.h"
#include "video/internal/ffmpeg_output.h"

namespace urdfsnap::video {

namespace {

// Animated WebP files larger than this are refused (docs animations are a few MB at most).
constexpr std::size_t kMaxWebpBytes = std::size_t{256} << 20;
// Frames of more pixels than this are refused before a decoder allocates them (8192 x 8192: a
// hostile header cannot make the reader take gigabytes).
constexpr std::int64_t kMaxFramePixels = std::int64_t{8192} * 8192;

std::string PixelLimitText() { return "more than urdfsnap's limit of 8192x8192 pixels for an animation frame"; }

class WebpReader final : public AnimationReader {
 public:
  explicit WebpReader(const std::string& path) : path_(path) {
    try {
      bytes_ = ReadFileBounded(path, kMaxWebpBytes);
    } catch (const FileReadError& e) {
      throw Error(path + ": cannot read: " + e.what());
    }
    const WebPData data{reinterpret_cast<const std::uint8_t*>(bytes_.data()), bytes_.size()};
    // the canvas size from the container, before the decoder allocates the canvas
    WebPDemuxer* demuxer = WebPDemux(&data);
    if (!demuxer) throw Error(path + ": not an animated WebP file libwebp can read");
    const std::int64_t pixels = std::int64_t{WebPDemuxGetI(demuxer, WEBP_FF_CANVAS_WIDTH)} *
                                WebPDemuxGetI(demuxer, WEBP_FF_CANVAS_HEIGHT);
    WebPDemuxDelete(demuxer);
    if (pixels > kMaxFramePixels) throw Error(path + ": a canvas of " + std::to_string(pixels) + " pixels, " + PixelLimitText());
    WebPAnimDecoderOptions options;
    WebPAnimDecoderOptionsInit(&options);
    options.color_mode = MODE_RGBA;
    decoder_ = WebPAnimDecoderNew(&data, &options);
    if (!decoder_ || !WebPAnimDecoderGetInfo(decoder_, &info_)) {
      throw Error(path + ": not an animated WebP file libwebp can read");
    }
  }
  ~WebpReader() override { WebPAnimDecoderDelete(decoder_); }

  bool Next(image::Image& frame, double& end_ms) override {
    if (!WebPAnimDecoderHasMoreFrames(decoder_)) return false;
    std::uint8_t* rgba = nullptr;
    int end = 0;
    if (!WebPAnimDecoderGetNext(decoder_, &rgba, &end)) throw Error(path_ + ": a frame does not decode");
    const int width = static_cast<int>(info_.canvas_width), height = static_cast<int>(info_.canvas_height);
    frame.width = width;
    frame.height = height;
    frame.rgb.resize(std::size_t(width) * height * 3);
    for (std::size_t p = 0; p < std::size_t(width) * height; ++p) {
      for (int c = 0; c < 3; ++c) frame.rgb[3 * p + c] = rgba[4 * p + c];
    }
    end_ms = end;
    return true;
  }

 private:
  std::string path_;
  std::string bytes_;
  WebPAnimDecoder* decoder_ = nullptr;
  WebPAnimInfo info_{};
};

// The demuxer's context, closed however the reader ends, also when its constructor throws after
// opening it (a file whose streams cannot be read, frames too large): avformat_close_input takes
// the pointer's address, so it has an owner of its own.
struct FormatContext {
  AVFormatContext* context = nullptr;
  ~FormatContext() { avformat_close_input(&context); }
};

class FfmpegReader final : public AnimationReader {
 public:
  explicit FfmpegReader(const std::string& path) : path_(path) {
    TakeOverFfmpegLog();
    CheckAv(avformat_open_input(&format_.context, path.c_str(), nullptr, nullptr), path, "cannot open");
    CheckAv(avformat_find_stream_info(format_.context, nullptr), path, "cannot read the stream");
    const AVCodec* codec = nullptr;
    stream_ = CheckAv(av_find_best_stream(format_.context, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0), path, "no video in it");
    codec_.reset(avcodec_alloc_context3(codec));
    CheckAv(avcodec_parameters_to_context(codec_.get(), format_.context->streams[stream_]->codecpar), path, "bad stream");
    if (std::int64_t{codec_->width} * codec_->height > kMaxFramePixels) {
      throw Error(path + ": frames of " + std::to_string(codec_->width) + "x" + std::to_string(codec_->height) +
                  " pixels, " + PixelLimitText());
    }
    codec_->max_pixels = kMaxFramePixels;   // frames that change size on the way too
    CheckAv(avcodec_open2(codec_.get(), codec, nullptr), path, "cannot open the decoder");
    packet_.reset(av_packet_alloc());
    decoded_.reset(av_frame_alloc());
  }
  ~FfmpegReader() override { sws_freeContext(scaler_); }

  bool Next(image::Image& frame, double& end_ms) override {
    while (true) {
      const int received = avcodec_receive_frame(codec_.get(), decoded_.get());
      if (received == 0) return Convert(frame, end_ms);
      if (received == AVERROR_EOF) return false;
      CheckAv(received == AVERROR(EAGAIN) ? 0 : received, path_, "a frame does not decode");
      // the decoder wants more: the next packet of the stream, or the end
      int read = av_read_frame(format_.context, packet_.get());
      while (read == 0 && packet_->stream_index != stream_) {
        av_packet_unref(packet_.get());
        read = av_read_frame(format_.context, packet_.get());
      }
      if (read == AVERROR_EOF) {
        CheckAv(avcodec_send_packet(codec_.get(), nullptr), path_, "cannot end the stream");
        continue;
      }
      CheckAv(read, path_, "cannot read a packet");
      const int sent = avcodec_send_packet(codec_.get(), packet_.get());
      av_packet_unref(packet_.get());
      CheckAv(sent, path_, "a packet does not decode");
    }
  }

 private:
  bool Convert(image::Image& frame, double& end_ms) {
    const AVFrame& in = *decoded_;
    scaler_ = sws_getCachedContext(scaler_, in.width, in.height, static_cast<AVPixelFormat>(in.format), in.width,
                                   in.height, AV_PIX_FMT_RGB24, SWS_BILINEAR, nullptr, nullptr, nullptr);
    if (!scaler_) throw Error(path_ + ": cannot convert its frames to RGB");
    frame.width = in.width;
    frame.height = in.height;
    frame.rgb.resize(std::size_t(in.width) * in.height * 3);
    std::uint8_t* planes[1] = {frame.rgb.data()};
    const int strides[1] = {in.width * 3};
    sws_scale(scaler_, in.data, in.linesize, 0, in.height, planes, strides);
    const AVRational base = format_.context->streams[stream_]->time_base;
    end_ms = 1000.0 * static_cast<double>(in.best_effort_timestamp + in.pkt_duration) * av_q2d(base);
    av_frame_unref(decoded_.get());
    return true;
  }

  std::string path_;
  FormatContext format_;
  int stream_ = -1;
  AvPointer<AVCodecContext> codec_;
  AvPointer<AVPacket> packet_;
  AvPointer<AVFrame> decoded_;
  SwsContext* scaler_ = nullptr;
};

}  // namespace

std::unique_ptr<AnimationReader> OpenAnimationFile(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".webp") return std::make_unique<WebpReader>(path);
  if (extension == ".gif" || extension == ".mp4" || extension == ".webm") return std::make_unique<FfmpegReader>(path);
  throw Error(path + ": not an animation urdfsnap reads (.gif, .webp, .mp4, .webm)");
}

}  // namespace urdfsnap::video
