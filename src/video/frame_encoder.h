// Writing an animation's frames to a file, the kind chosen by the output's extension: .mp4 (H.264),
// .webm (VP9), .gif, .webp (animated), or a numbered PNG sequence such as frames/%05d.png. One
// interface for all: open with the size and frame rate, write the frames in order, finish. Every
// encoder streams (memory does not grow with the number of frames), writes to temporary files and
// moves the result into place only when finished, so an error never leaves a partial output.
// Encoders are opened by OpenFrameEncoder (open_frame_encoder.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "image/image.h"
#include "video/numbered_files.h"

namespace urdfsnap::video {

enum class OutputFormat {
  kMp4,          // H.264 (libx264), yuv420p, BT.709, moov atom first ("faststart") for browsers
  kWebm,         // VP9 (libvpx), yuv420p, constant quality
  kGif,          // one 256-colour palette for the whole animation, dithered
  kWebp,         // animated WebP (libwebp's animation encoder), lossy
  kPngSequence,  // one PNG per frame, named by a printf pattern ("%05d"), numbered from 0
};

// The format for `path`: a pattern with one %d conversion and a .png extension is a PNG sequence,
// else the extension decides (case-insensitive). Throws Error naming the path and the formats
// urdfsnap writes for anything else.
OutputFormat OutputFormatOf(const std::string& path);

// What an animation in a format gets when `animate` is given no --fps or --size: 30 frames/s at
// 640x480 (RViz's reference render area), but 15 frames/s at 480x360 for GIF, whose frames are
// each a full palette image under LZW (a 10 s Panda turntable at 30 frames/s and 640x480 is ten
// times the MP4's size; at these it is a quarter of that). Explicit options always win.
struct FormatDefaults {
  double fps;
  const char* size;   // as --size takes it
};
FormatDefaults DefaultsFor(OutputFormat format);

// "MP4 (H.264)", "PNG sequence", ...: for messages.
const char* OutputFormatName(OutputFormat format);

struct EncoderSettings {
  int width = 0;  // pixels, as the frames will be
  int height = 0;
  double fps = 30;  // frames per second, > 0
  // The number of the first frame written: a PNG sequence's first file is named with it (a shard
  // of a sequence, --shard). A video is one file of every frame, so it only starts at 0.
  std::int64_t first_frame = 0;
  Staging staging = {};   // a PNG sequence drawn by worker processes (see NumberedFiles)
};

class FrameEncoder {
 public:
  // Destroyed without Finish (after an error), an encoder removes what it had written.
  virtual ~FrameEncoder() = default;

  // Encodes the next frame, which must have the size the encoder was opened with. Throws Error
  // (a wrong size, a failing write such as a full disk).
  virtual void Write(const image::Image& frame) = 0;

  // Completes the output and moves it into place. Throws Error; then nothing is left behind.
  virtual void Finish() = 0;
};

}  // namespace urdfsnap::video
