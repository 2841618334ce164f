// EncodedOutput on libavcodec's send/receive API and libavformat's interleaving writer; FFmpeg's
// log captured through av_log_set_callback.
#include "video/internal/ffmpeg_output.h"

extern "C" {
#include <libavutil/imgutils.h>
}

#include <cstdarg>
#include <cstdio>
#include <mutex>

#include "common/error.h"

namespace urdfsnap::video {
namespace {

// the last error-level line FFmpeg logged on this thread (its return codes are terse)
thread_local std::string last_log_error;

void LogCallback(void* avcl, int level, const char* format, va_list arguments) {
  if (level > AV_LOG_ERROR) return;
  char line[1024];
  std::vsnprintf(line, sizeof line, format, arguments);
  std::string text = line;
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const AVClass* const* object = static_cast<const AVClass* const*>(avcl);
  if (object && *object) text = std::string((*object)->item_name(avcl)) + ": " + text;
  last_log_error = text;
}

// FFmpeg leaves the options it did not know in the dictionary: a misspelt one is a bug here.
void CheckAllUsed(AvOptions& options, const std::string& output, const char* user) {
  if (const AVDictionaryEntry* unknown =
          av_dict_get(*options.get(), "", nullptr, AV_DICT_IGNORE_SUFFIX)) {
    throw Error(output + ": " + user + " has no option '" + unknown->key + "'");
  }
}

}  // namespace

void TakeOverFfmpegLog() {
  static std::once_flag once;
  std::call_once(once, [] { av_log_set_callback(LogCallback); });
}

int CheckAv(int result, const std::string& output, const std::string& what) {
  if (result >= 0) return result;
  char reason[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(result, reason, sizeof reason);
  std::string message = output + ": " + what + ": " + reason;
  if (!last_log_error.empty()) message += " (" + last_log_error + ")";
  last_log_error.clear();
  throw Error(message);
}

AVRational FrameRate(double fps) { return av_d2q(fps, 1'000'000); }

AvPointer<AVFrame> MakeFrame(AVPixelFormat format, int width, int height,
                             const std::string& output) {
  AvPointer<AVFrame> frame(av_frame_alloc());
  if (!frame) throw std::bad_alloc();
  frame->format = format;
  frame->width = width;
  frame->height = height;
  CheckAv(av_frame_get_buffer(frame.get(), 0), output, "cannot allocate a frame");
  return frame;
}

EncodedOutput::EncodedOutput(AtomicFile& file, const char* muxer, const AVCodec* codec,
                             AVRational frame_rate,
                             const std::function<void(AVCodecContext*)>& configure,
                             AvOptions& codec_options, AvOptions& muxer_options)
    : file_(file), packet_(av_packet_alloc()) {
  const std::string& output = file.path();
  if (!codec) throw Error(output + ": FFmpeg's libraries have no such encoder installed");
  if (!packet_) throw std::bad_alloc();
  // the muxer writes the temporary file by its name (an MP4's faststart reopens it to move the
  // index to the front)
  CheckAv(avformat_alloc_output_context2(&format_, nullptr, muxer, file.temp_path().c_str()),
          output, std::string("cannot make a ") + muxer + " muxer");
  codec_.reset(avcodec_alloc_context3(codec));
  if (!codec_) throw std::bad_alloc();
  codec_->time_base = av_inv_q(frame_rate);
  codec_->framerate = frame_rate;
  configure(codec_.get());
  if (format_->oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  CheckAv(avcodec_open2(codec_.get(), codec, codec_options.get()), output,
          std::string("cannot open the ") + codec->name + " encoder");
  CheckAllUsed(codec_options, output, codec->name);

  stream_ = avformat_new_stream(format_, nullptr);
  if (!stream_) throw std::bad_alloc();
  stream_->time_base = codec_->time_base;
  stream_->avg_frame_rate = frame_rate;
  CheckAv(avcodec_parameters_from_context(stream_->codecpar, codec_.get()), output,
          "cannot describe the stream");
  CheckAv(avio_open(&format_->pb, file.temp_path().c_str(), AVIO_FLAG_WRITE), output,
          "cannot write");
  CheckAv(avformat_write_header(format_, muxer_options.get()), output, "cannot write the header");
  CheckAllUsed(muxer_options, output, muxer);
}

EncodedOutput::~EncodedOutput() {
  if (format_) {
    avio_closep(&format_->pb);
    avformat_free_context(format_);
  }
}

void EncodedOutput::WritePackets() {
  while (true) {
    const int result = avcodec_receive_packet(codec_.get(), packet_.get());
    if (result == AVERROR(EAGAIN) || result == AVERROR_EOF) return;
    CheckAv(result, file_.path(), "cannot encode");
    av_packet_rescale_ts(packet_.get(), codec_->time_base, stream_->time_base);
    packet_->stream_index = stream_->index;
    CheckAv(av_interleaved_write_frame(format_, packet_.get()), file_.path(), "cannot write");
  }
}

void EncodedOutput::Send(const AVFrame* frame) {
  CheckAv(avcodec_send_frame(codec_.get(), frame), file_.path(), "cannot encode");
  WritePackets();
}

void EncodedOutput::Finish() {
  Send(nullptr);
  CheckAv(av_write_trailer(format_), file_.path(), "cannot finish");
  CheckAv(avio_closep(&format_->pb), file_.path(), "cannot write");
}

}  // namespace urdfsnap::video
