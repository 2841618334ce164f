// The FFmpeg plumbing the MP4, WebM and GIF encoders share: error text (FFmpeg's own log lines are
// caught and put into urdfsnap's error instead of going to stderr), owning pointers for its
// structures, and EncodedOutput: one opened encoder whose packets a muxer writes into the
// temporary file of an AtomicFile.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
}

#include <functional>
#include <memory>
#include <string>

#include "common/atomic_file.h"

namespace urdfsnap::video {

// Sends FFmpeg's log to urdfsnap instead of stderr (messages of error level are kept for the next
// error, the rest dropped). Call before using FFmpeg; it is process-wide and idempotent.
void TakeOverFfmpegLog();

// Throws Error "OUTPUT: WHAT: <FFmpeg's reason>" when `result` is negative; returns it otherwise.
int CheckAv(int result, const std::string& output, const std::string& what);

// `fps` as the rational FFmpeg wants (29.97 -> 2997/100).
AVRational FrameRate(double fps);

struct AvFreer {
  void operator()(AVCodecContext* context) const { avcodec_free_context(&context); }
  void operator()(AVFrame* frame) const { av_frame_free(&frame); }
  void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};
template <typename T>
using AvPointer = std::unique_ptr<T, AvFreer>;

// Options for an encoder or a muxer ("preset" = "veryfast"), freed with the object.
class AvOptions {
 public:
  AvOptions() = default;
  ~AvOptions() { av_dict_free(&dictionary_); }
  AvOptions(const AvOptions&) = delete;
  AvOptions& operator=(const AvOptions&) = delete;

  AvOptions& Set(const char* key, const char* value) {
    av_dict_set(&dictionary_, key, value, 0);
    return *this;
  }
  AVDictionary** get() { return &dictionary_; }

 private:
  AVDictionary* dictionary_ = nullptr;
};

// A frame of `format` and size with its own buffers (throws Error for `output` on failure).
AvPointer<AVFrame> MakeFrame(AVPixelFormat format, int width, int height,
                             const std::string& output);

// An encoder and the muxer that writes what it makes to `file`'s temporary file.
class EncodedOutput {
 public:
  // `configure` fills the codec context (size, pixel format) before it is opened with
  // `codec_options`; `muxer` is FFmpeg's format name ("mp4", "webm", "gif"). Throws Error naming
  // file.path() when the encoder or muxer cannot be opened, or does not know an option.
  EncodedOutput(AtomicFile& file, const char* muxer, const AVCodec* codec, AVRational frame_rate,
                const std::function<void(AVCodecContext*)>& configure, AvOptions& codec_options,
                AvOptions& muxer_options);
  ~EncodedOutput();

  EncodedOutput(const EncodedOutput&) = delete;
  EncodedOutput& operator=(const EncodedOutput&) = delete;

  AVCodecContext* codec() { return codec_.get(); }

  // Encodes `frame` (its pts in frames) and writes the packets that come out.
  void Send(const AVFrame* frame);
  // Flushes the encoder, writes the muxer's trailer and closes the file (AtomicFile::Commit is the
  // caller's).
  void Finish();

 private:
  void WritePackets();

  AtomicFile& file_;
  AvPointer<AVCodecContext> codec_;
  AVFormatContext* format_ = nullptr;
  AVStream* stream_ = nullptr;
  AvPointer<AVPacket> packet_;
};

}  // namespace urdfsnap::video
