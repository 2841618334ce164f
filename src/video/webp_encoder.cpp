// WebpEncoder: RIFF/WEBP container with VP8X and ANIM chunks, then one ANMF chunk per frame as
// libwebp's animation encoder made it (see developers.google.com/speed/webp/docs/riff_container).
#include "video/internal/webp_encoder.h"

#include <webp/demux.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <cmath>
#include <limits>

#include "common/atomic_file.h"
#include "common/error.h"
#include "video/internal/frame_size.h"

namespace urdfsnap::video {
namespace {

constexpr int kMaxWebpSide = 16383;
// frames per segment: a keyframe at each segment start costs little at this length, and a
// segment's encoded frames are a few megabytes at most
constexpr int kFramesPerSegment = 120;
// lossy quality and effort: sharp enough for robot edges, and fast (bench/video)
constexpr float kQuality = 85;
constexpr int kMethod = 2;
constexpr std::uint32_t kAnimationFlag = 0x02;  // VP8X flags (the container's bit for animation)
constexpr std::size_t kVp8xFlagsOffset = 20;    // "RIFF" size "WEBP" "VP8X" size, then the flags

void PutLittleEndian(std::string& bytes, std::uint64_t value, int count) {
  for (int i = 0; i < count; ++i) bytes += static_cast<char>((value >> (8 * i)) & 0xff);
}

std::string Chunk(const char* fourcc, const std::string& payload) {
  std::string chunk(fourcc, 4);
  PutLittleEndian(chunk, payload.size(), 4);
  chunk += payload;
  if (payload.size() % 2 == 1) chunk += '\0';
  return chunk;
}

struct AnimEncoderFreer {
  void operator()(WebPAnimEncoder* encoder) const { WebPAnimEncoderDelete(encoder); }
};

class WebpEncoder final : public FrameEncoder {
 public:
  WebpEncoder(const std::string& path, const EncoderSettings& settings)
      : settings_(settings), file_(path) {
    if (!WebPConfigInit(&config_) || !WebPPictureInit(&picture_)) {
      throw Error(path + ": libwebp's version does not match its headers");
    }
    config_.quality = kQuality;
    config_.method = kMethod;
    picture_.width = settings.width;
    picture_.height = settings.height;
    picture_.use_argb = 1;
    // the header, with the file size and the flags filled in by Finish
    std::string vp8x;
    PutLittleEndian(vp8x, kAnimationFlag, 4);
    PutLittleEndian(vp8x, settings.width - 1, 3);
    PutLittleEndian(vp8x, settings.height - 1, 3);
    std::string anim;
    PutLittleEndian(anim, 0xffffffff, 4);  // background: white, a hint viewers may ignore
    PutLittleEndian(anim, 0, 2);           // loop forever
    const std::string header = "RIFF____WEBP" + Chunk("VP8X", vp8x) + Chunk("ANIM", anim);
    file_.Write(header);
    size_ = header.size();
  }

  ~WebpEncoder() override { WebPPictureFree(&picture_); }

  void Write(const image::Image& frame) override {
    CheckFrameSize(frame, settings_, file_.path());
    if (!segment_) StartSegment();
    if (!WebPPictureImportRGB(&picture_, frame.rgb.data(), 3 * frame.width)) {
      throw Error(file_.path() + ": libwebp cannot take a frame (out of memory)");
    }
    if (!WebPAnimEncoderAdd(segment_.get(), &picture_, SegmentTime(frames_), &config_)) {
      throw Error(file_.path() +
                  ": libwebp cannot encode a frame: " + WebPAnimEncoderGetError(segment_.get()));
    }
    ++frames_;
    if (frames_ - segment_start_ == kFramesPerSegment) EndSegment();
  }

  void Finish() override {
    if (segment_) EndSegment();
    if (frames_ == 0) throw Error(file_.path() + ": an animation without frames");
    std::string riff_size, flags;
    PutLittleEndian(riff_size, size_ - 8, 4);
    flags += static_cast<char>(flags_ | kAnimationFlag);
    file_.WriteAt(4, riff_size);
    file_.WriteAt(kVp8xFlagsOffset, flags);
    file_.Commit();
  }

 private:
  // Milliseconds of frame `frame` from the current segment's start (rounded from the animation's
  // start, so that durations add up over segments).
  int SegmentTime(std::int64_t frame) const {
    const auto ms = [&](std::int64_t k) { return std::llround(k * 1000.0 / settings_.fps); };
    return static_cast<int>(ms(frame) - ms(segment_start_));
  }

  void StartSegment() {
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options)) {
      throw Error(file_.path() + ": libwebp's version does not match its headers");
    }
    options.anim_params.loop_count = 0;
    segment_.reset(WebPAnimEncoderNew(settings_.width, settings_.height, &options));
    if (!segment_) throw Error(file_.path() + ": libwebp cannot start an animation");
    segment_start_ = frames_;
  }

  // Assembles the segment and appends its frames to the file as ANMF chunks.
  void EndSegment() {
    WebPAnimEncoder* encoder = segment_.get();
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAdd(encoder, nullptr, SegmentTime(frames_), nullptr) ||
        !WebPAnimEncoderAssemble(encoder, &data)) {
      throw Error(file_.path() +
                  ": libwebp cannot finish a segment: " + WebPAnimEncoderGetError(encoder));
    }
    WebPDemuxer* demuxer = WebPDemux(&data);
    if (!demuxer) {
      WebPDataClear(&data);
      throw Error(file_.path() + ": libwebp made a segment it cannot read back");
    }
    flags_ |= WebPDemuxGetI(demuxer, WEBP_FF_FORMAT_FLAGS);
    WebPIterator frame;
    std::string chunks;
    if (WebPDemuxGetFrame(demuxer, 1, &frame)) {
      do {
        // ANMF: offsets / 2, size - 1, duration (24 bits each), then the blending and disposal
        // bits, then the frame's ALPH/VP8/VP8L chunks as the encoder wrote them
        std::string anmf;
        PutLittleEndian(anmf, frame.x_offset / 2, 3);
        PutLittleEndian(anmf, frame.y_offset / 2, 3);
        PutLittleEndian(anmf, frame.width - 1, 3);
        PutLittleEndian(anmf, frame.height - 1, 3);
        PutLittleEndian(anmf, frame.duration, 3);
        anmf += static_cast<char>((frame.blend_method == WEBP_MUX_NO_BLEND ? 0x02 : 0) |
                                  (frame.dispose_method == WEBP_MUX_DISPOSE_BACKGROUND ? 0x01 : 0));
        anmf.append(reinterpret_cast<const char*>(frame.fragment.bytes), frame.fragment.size);
        chunks += Chunk("ANMF", anmf);
      } while (WebPDemuxNextFrame(&frame));
      WebPDemuxReleaseIterator(&frame);
    }
    WebPDemuxDelete(demuxer);
    WebPDataClear(&data);
    if (size_ + chunks.size() > std::numeric_limits<std::uint32_t>::max() - 8) {
      throw Error(file_.path() + ": an animated WebP cannot be larger than 4 GiB");
    }
    file_.Write(chunks);
    size_ += chunks.size();
    segment_.reset();
  }

  EncoderSettings settings_;
  AtomicFile file_;
  WebPConfig config_;
  WebPPicture picture_;
  std::unique_ptr<WebPAnimEncoder, AnimEncoderFreer> segment_;
  std::int64_t frames_ = 0;
  std::int64_t segment_start_ = 0;
  std::uint64_t size_ = 0;  // bytes written
  std::uint32_t flags_ = 0;
};

}  // namespace

std::unique_ptr<FrameEncoder> OpenWebpEncoder(const std::string& path,
                                              const EncoderSettings& settings) {
  if (settings.width > kMaxWebpSide || settings.height > kMaxWebpSide) {
    throw Error(path + ": WebP images are at most " + std::to_string(kMaxWebpSide) +
                " pixels on a side, not " + std::to_string(settings.width) + "x" +
                std::to_string(settings.height));
  }
  return std::make_unique<WebpEncoder>(path, settings);
}

}  // namespace urdfsnap::video
