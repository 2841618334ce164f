// A distorted (raw) camera image made from a pinhole render: OpenCV's initUndistortRectifyMap read
// the other way round. For each raw pixel the ideal ray is found once (Undistort); each frame then
// takes its colour from the pinhole image bilinearly and its depth and link label from the nearest
// pinhole pixel, so depth and labels stay exact values of one surface and agree with each other.
#pragma once

#include <cstdint>
#include <vector>

#include "camera/distortion.h"
#include "camera/pinhole.h"
#include "image/image.h"

namespace urdfsnap::camera {

// A pinhole image: intrinsics and size in pixels.
struct PinholeImage {
  Intrinsics k;
  int width = 0;
  int height = 0;
};

class DistortionRemap {
 public:
  // The raw image `raw` with lens distortion `d`. Chooses the pinhole image to render (source()):
  // the raw focal lengths, wide enough to hold the ray of every raw pixel, at most three times the
  // raw size per side (focal lengths reduced to fit a wider field). Raw pixels the lens gives no
  // ray (Undistort fails) come out black, without depth or label.
  DistortionRemap(const PinholeImage& raw, const Distortion& d);

  const PinholeImage& source() const { return source_; }

  // The raw frame of a frame rendered through source(): colour, depth and labels as present.
  // Throws urdfsnap::Error when a present image does not have source()'s size.
  image::Frame Apply(const image::Frame& source) const;

 private:
  // where one raw pixel comes from: the nearest source pixel (−1: no ray) and the top-left pixel
  // and fractions of its bilinear square
  struct Sample {
    std::int32_t nearest = -1;
    std::int32_t corner = 0;
    float fx = 0, fy = 0;
  };
  PinholeImage raw_;
  PinholeImage source_;
  std::vector<Sample> samples_;   // raw width x height, top row first
};

}  // namespace urdfsnap::camera
