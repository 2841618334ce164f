// ImageFromRos: the row layout checked against the data, then each encoding's samples read into
// RGB; ImageFromCompressed: JPEG or PNG by the data's first bytes.
#include "camera/ros_image.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "common/error.h"
#include "image/jpeg_reader.h"
#include "image/png_reader.h"

namespace urdfsnap::camera {
namespace {

// How an encoding's pixels are laid out: bytes per pixel and where red, green, blue are (grey
// encodings: all three at the one sample).
struct Layout {
  int bytes = 0;
  int r = 0, g = 0, b = 0;
  enum class Sample { kByte, kUint16, kFloat32 } sample = Sample::kByte;
};

Layout LayoutOf(const std::string& encoding, const std::string& where) {
  using S = Layout::Sample;
  if (encoding == "rgb8") return {3, 0, 1, 2};
  if (encoding == "bgr8" || encoding == "8UC3" || encoding == "8SC3") return {3, 2, 1, 0};
  if (encoding == "rgba8") return {4, 0, 1, 2};
  if (encoding == "bgra8" || encoding == "8UC4" || encoding == "8SC4") return {4, 2, 1, 0};
  if (encoding == "mono8" || encoding == "8UC1" || encoding == "8SC1") return {1, 0, 0, 0};
  if (encoding == "mono16" || encoding == "16UC1") return {2, 0, 0, 0, S::kUint16};
  if (encoding == "32FC1") return {4, 0, 0, 0, S::kFloat32};
  throw Error(where + ": image encoding '" + encoding + "' is not one urdfsnap shows (rgb8, bgr8, rgba8, bgra8, "
              "mono8, mono16, 16UC1, 32FC1, as RViz's Camera display)");
}

// The sample of pixel `x` of the row at `row`, as a number, in the message's byte order.
double SampleAt(const std::uint8_t* row, int x, const Layout& layout, bool big_endian) {
  const std::uint8_t* p = row + std::size_t(x) * layout.bytes;
  if (layout.sample == Layout::Sample::kUint16) {
    return big_endian ? (p[0] << 8 | p[1]) : (p[1] << 8 | p[0]);
  }
  std::uint32_t bits = 0;
  for (int k = 0; k < 4; ++k) bits |= std::uint32_t(p[big_endian ? k : 3 - k]) << (8 * (3 - k));
  return std::bit_cast<float>(bits);
}

// A 16- or 32-bit grey image scaled to 8 bits as ROSImageTexture normalises it: the smallest
// finite value black, the largest white, truncated (val · 255); all black when they are equal.
void ScaleGrey(const RosImage& m, const Layout& layout, image::Image& out) {
  std::vector<double> values(std::size_t(m.width) * m.height);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::uint32_t y = 0; y < m.height; ++y) {
    const std::uint8_t* row = m.data.data() + std::size_t(y) * m.step;
    for (std::uint32_t x = 0; x < m.width; ++x) {
      const double v = SampleAt(row, static_cast<int>(x), layout, m.is_bigendian);
      values[std::size_t(y) * m.width + x] = v;
      if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
    }
  }
  const double range = high - low;
  for (std::size_t i = 0; i < values.size(); ++i) {
    double v = range > 0 && std::isfinite(values[i]) ? (values[i] - low) / range : 0;
    const auto grey = static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255);
    std::memset(&out.rgb[3 * i], grey, 3);
  }
}

}  // namespace

image::Image ImageFromRos(const RosImage& m, const std::string& where) {
  const Layout layout = LayoutOf(m.encoding, where);
  constexpr std::uint32_t kSide = image::kMaxImageSide;
  if (m.width == 0 || m.height == 0 || m.width > kSide || m.height > kSide) {
    throw Error(where + ": image size " + std::to_string(m.width) + "x" + std::to_string(m.height) +
                " is outside 1x1 to " + image::SizeText(image::kMaxImageSide, image::kMaxImageSide));
  }
  const std::uint64_t row = std::uint64_t{m.width} * layout.bytes;
  if (m.step < row) {
    throw Error(where + ": step " + std::to_string(m.step) + " is shorter than a row of " + std::to_string(m.width) +
                " " + m.encoding + " pixels (" + std::to_string(row) + " bytes)");
  }
  // the last row needs only its pixels, not its padding
  const std::uint64_t needed = std::uint64_t{m.step} * (m.height - 1) + row;
  if (m.data.size() < needed) {
    throw Error(where + ": " + std::to_string(m.data.size()) + " bytes of data, too few for " +
                image::SizeText(static_cast<int>(m.width), static_cast<int>(m.height)) + " pixels at step " +
                std::to_string(m.step) + " (" + std::to_string(needed) + " bytes)");
  }
  image::Image out;
  out.width = static_cast<int>(m.width);
  out.height = static_cast<int>(m.height);
  out.rgb.resize(std::size_t(out.width) * out.height * 3);
  if (layout.sample != Layout::Sample::kByte) {
    ScaleGrey(m, layout, out);
    return out;
  }
  for (int y = 0; y < out.height; ++y) {
    const std::uint8_t* row_data = m.data.data() + std::size_t(y) * m.step;
    std::uint8_t* to = &out.rgb[std::size_t(y) * out.width * 3];
    for (int x = 0; x < out.width; ++x, to += 3) {
      const std::uint8_t* p = row_data + std::size_t(x) * layout.bytes;
      to[0] = p[layout.r];
      to[1] = p[layout.g];
      to[2] = p[layout.b];
    }
  }
  return out;
}

image::Image ImageFromCompressed(std::string_view format, std::span<const std::uint8_t> data,
                                 const std::string& where) {
  const std::string_view bytes(reinterpret_cast<const char*>(data.data()), data.size());
  if (image::LooksLikeJpeg(bytes)) return image::DecodeJpeg(bytes, where);
  if (bytes.size() >= 4 && bytes.substr(1, 3) == "PNG") return image::DecodePng(bytes, where);
  throw Error(where + ": compressed image of format '" + std::string(format) +
              "' is neither JPEG nor PNG (urdfsnap shows those two)");
}

}  // namespace urdfsnap::camera
