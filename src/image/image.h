// The pixel buffers every stage hands on, rows from top to bottom (PNG order; GL's read-back is
// bottom-up, the GL stage flips it): the 8-bit RGB colour image, and the depth and link-label
// images rendered beside it; and Frame, what one render returns.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace urdfsnap::image {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3 bytes, row after row, top row first
};

// Distance from the camera along its viewing axis, in metres; NaN where no robot geometry is.
struct DepthImage {
  int width = 0;
  int height = 0;
  std::vector<float> metres;   // width * height, top row first
};

// 1 + the index of the robot link whose geometry is nearest at each pixel (links in Robot::links()
// order, as `urdfsnap info` lists them); 0 where there is none.
struct LabelImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> labels;   // width * height, top row first
};

// A 16-bit single-channel image as stored in a PNG: depth in millimetres, or link labels.
struct Gray16Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> values;   // width * height, top row first
};

// An 8-bit single-channel image: a binary mask (0 or 255).
struct Gray8Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> values;   // width * height, top row first
};

// Which images a render produces; all come from the same view and pose.
struct FrameOutputs {
  bool colour = true;
  bool depth = false;
  bool labels = false;
};

// The images of one render; those not asked for are empty (0x0).
struct Frame {
  Image colour;
  DepthImage depth;
  LabelImage labels;
};

// The largest width and height urdfsnap encodes or decodes, in pixels: far above any render, and
// small enough that a crafted PNG header cannot make a reader allocate gigabytes.
inline constexpr int kMaxImageSide = 16384;

// Throws urdfsnap::Error naming `role` ("EncodePng", "expected image", ...) unless the image has a
// positive size within kMaxImageSide and rgb holds exactly width * height * 3 bytes.
void CheckImage(const Image& image, std::string_view role);

// CheckImage's size check alone, for images of other pixel types.
void CheckImageSize(int width, int height, std::string_view role);

// "640x480".
std::string SizeText(const Image& image);
std::string SizeText(int width, int height);

}  // namespace urdfsnap::image
