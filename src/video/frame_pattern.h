// Names of numbered frame files from a printf-style pattern, as in `-o frames/%05d.png` (and in
// FFmpeg's image2 muxer): exactly one integer conversion, %d or %i with an optional 0 flag and
// width; %% is a literal percent sign.
#pragma once

#include <cstdint>
#include <string>

namespace urdfsnap::video {

class FramePattern {
 public:
  // Throws Error "PATTERN: ..." when the pattern has no integer conversion, more than one, or
  // another conversion (%s, %f, %5.2d, ...).
  explicit FramePattern(std::string pattern);

  // Whether `path` contains a frame-number conversion at all (a pattern rather than one file).
  static bool IsPattern(const std::string& path);

  // The file name of frame `number` ("frames/00042.png").
  std::string Name(std::int64_t number) const;

  const std::string& pattern() const { return pattern_; }
  // The names around the number: Name(k) is prefix() + the number + suffix().
  const std::string& prefix() const { return prefix_; }
  const std::string& suffix() const { return suffix_; }

 private:
  std::string pattern_;
  std::string prefix_, suffix_;  // with %% already turned into %
  int width_ = 0;
  bool zero_pad_ = false;
};

}  // namespace urdfsnap::video
