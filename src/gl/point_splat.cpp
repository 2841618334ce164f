// PointSplat: each point projected as shaders/point.vert and point_quad.vert place it, its square
// covered sample by sample, coloured as shaders/point.frag colours it.
#include "gl/internal/point_splat.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <system_error>
#include <thread>

namespace urdfsnap::gl {

namespace {

// GL's conversion of a colour channel to 8 bits (round to nearest)
std::uint32_t Byte(float value) { return static_cast<std::uint32_t>(std::clamp(value, 0.f, 1.f) * 255.f + 0.5f); }

float Channel8(float value) { return static_cast<float>(Byte(value)) / 255.f; }

std::uint32_t Pack(const Eigen::Vector3f& rgb, float alpha) {
  return Byte(rgb[0]) | Byte(rgb[1]) << 8 | Byte(rgb[2]) << 16 | Byte(alpha) << 24;
}

// ceil for window coordinates, without a libm call; a square reaching far off the screen (a big
// one near the camera) is held at a million pixels, well within int
int Ceil(float v) {
  v = std::clamp(v, -1e6f, 1e6f);
  const int i = static_cast<int>(v);
  return i + (static_cast<float>(i) < v);
}

float Smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.f, 1.f);
  return t * t * (3.f - 2.f * t);
}

// shaders/point.frag at square coordinates (u, v) in [0, 1]; false where the disc discards
bool Shade(int shape, float u, float v, Eigen::Vector3f& c) {
  const float ax = u - 0.5f, ay = v - 0.5f;
  if (shape == 1) {
    const float blend = Smoothstep(-0.48f, -0.45f, ay) * (1.f - Smoothstep(0.45f, 0.48f, ay)) *
                        Smoothstep(-0.48f, -0.45f, ax) * (1.f - Smoothstep(0.45f, 0.48f, ax));
    const float sign = c.norm() < 0.5f ? 1.f : c.norm() > 0.5f ? -1.f : 0.f;
    c = blend * c + (Eigen::Vector3f::Constant(sign * 0.2f) + c) * (1.f - blend);
  } else if (shape == 2) {
    const float a = (0.25f - (ax * ax + ay * ay)) * 4.f;
    if (a <= 0.f) return false;
    c = 0.8f * c + (c - 0.8f * c) * a;
  }
  return true;
}

}  // namespace

void PointSplat::Clear(int width, int height, const std::vector<Eigen::Vector2f>& samples) {
  width_ = width;
  height_ = height;
  samples_ = samples;
  sample_min_ = sample_max_ = samples.front();
  for (const Eigen::Vector2f& s : samples) sample_min_ = sample_min_.cwiseMin(s), sample_max_ = sample_max_.cwiseMax(s);
  const std::size_t size = static_cast<std::size_t>(width) * height * samples.size();
  texels_.assign(size, Texel{kEmpty, 0});
  rows_ = {height, -1};
  squares_.clear();
}

void PointSplat::Keep(float x0, float x1, float y0, float y1, float depth, const Eigen::Vector4f& rgba, int shape) {
  // llvmpipe snaps vertices to 1/256 pixel (lp_setup's FIXED_ORDER 8) before it tests samples
  const auto snap = [](float v) { return std::round(v * 256.f) / 256.f; };
  if (!std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y0) || !std::isfinite(y1) || !std::isfinite(depth)) {
    return;   // a point at infinity: GL would draw nothing either
  }
  Square square{snap(x0), snap(x1), snap(y0), snap(y1), depth, rgba, shape, 0, 0, 0, 0};
  square.px0 = std::max(0, Ceil(square.x0 - sample_max_.x()));
  square.px1 = std::min(width_ - 1, Ceil(square.x1 - sample_min_.x()) - 1);
  square.py0 = std::max(0, Ceil(square.y0 - sample_max_.y()));
  square.py1 = std::min(height_ - 1, Ceil(square.y1 - sample_min_.y()) - 1);
  if (square.px0 <= square.px1 && square.py0 <= square.py1) squares_.push_back(square);
}

bool PointSplat::CoverSquare(const Square& square, int first, int last) {
  const Eigen::Vector3f flat = square.rgba.head<3>();
  const std::uint32_t flat_packed = Pack(flat, square.rgba[3]);
  const std::size_t count = samples_.size();
  bool drawn = false;
  Texel* const texels = texels_.data();
  const float depth = square.depth;
  const auto cover = [&](std::size_t at, std::uint32_t packed) {
    if (depth > texels[at].depth) return;
    texels[at] = {depth, packed};
    drawn = true;
  };
  if (square.shape == 0) {
    // one colour: each sample's own rows and columns of pixels whose sample lies inside, where x
    // in [x0, x1) is px in [ceil(x0 - sx), ceil(x1 - sx))
    for (std::size_t s = 0; s < count; ++s) {
      const Eigen::Vector2f& sample = samples_[s];
      const int px0 = std::max(0, Ceil(square.x0 - sample.x()));
      const int px1 = std::min(width_, Ceil(square.x1 - sample.x()));
      const int py0 = std::max(first, Ceil(square.y0 - sample.y()));
      const int py1 = std::min(last + 1, Ceil(square.y1 - sample.y()));
      for (int py = py0; py < py1; ++py) {
        for (int px = px0; px < px1; ++px) cover((static_cast<std::size_t>(py) * width_ + px) * count + s, flat_packed);
      }
    }
    return drawn;
  }
  // shaded: the colour at each pixel's centre, for the samples of the pixel inside the square
  for (int py = std::max(square.py0, first); py <= std::min(square.py1, last); ++py) {
    for (int px = square.px0; px <= square.px1; ++px) {
      Eigen::Vector3f c = flat;
      const float u = (static_cast<float>(px) + 0.5f - square.x0) / (square.x1 - square.x0);
      const float v = (static_cast<float>(py) + 0.5f - square.y0) / (square.y1 - square.y0);
      if (!Shade(square.shape, u, v, c)) continue;
      const std::uint32_t packed = Pack(c, square.rgba[3]);
      const std::size_t pixel = (static_cast<std::size_t>(py) * width_ + px) * count;
      for (std::size_t s = 0; s < count; ++s) {
        const float x = static_cast<float>(px) + samples_[s].x(), y = static_cast<float>(py) + samples_[s].y();
        // a sample on the left or lower edge is in, on the right or upper one out: what llvmpipe's
        // fill rule gives in urdfsnap's flipped framebuffer (the GL-drawn goldens agree)
        if (x >= square.x0 && x < square.x1 && y >= square.y0 && y < square.y1) cover(pixel + s, packed);
      }
    }
  }
  return drawn;
}

void PointSplat::CoverBand(int first, int last, std::pair<int, int>& rows) {
  for (const Square& square : sorted_) {
    if (square.py0 > last) break;   // the rest start above the band
    if (square.py1 < first || !CoverSquare(square, first, last)) continue;
    rows = {std::min(rows.first, std::max(square.py0, first)), std::max(rows.second, std::min(square.py1, last))};
  }
}

void PointSplat::Cover() {
  // a stable counting sort by first row keeps the order of squares that start on the same row
  std::vector<std::size_t> starts(static_cast<std::size_t>(height_) + 1, 0);
  for (const Square& square : squares_) ++starts[static_cast<std::size_t>(square.py0) + 1];
  for (std::size_t row = 1; row < starts.size(); ++row) starts[row] += starts[row - 1];
  sorted_.resize(squares_.size());
  for (const Square& square : squares_) sorted_[starts[static_cast<std::size_t>(square.py0)]++] = square;
  squares_.clear();
  // two bands of rows, split where half the squares start: a texel is written by one thread only,
  // in the squares' order, so the image is the same as from one thread. Few squares are not worth
  // a thread.
  const int middle = sorted_.size() >= kSquaresPerThread ? sorted_[sorted_.size() / 2].py0 : height_;
  std::pair<int, int> upper{height_, -1};
  std::optional<std::thread> helper;
  if (middle < height_ && std::thread::hardware_concurrency() > 1) {
    try {
      helper.emplace([&] { CoverBand(middle, height_ - 1, upper); });
    } catch (const std::system_error&) {
      // no thread to be had: this one covers both bands
    }
  }
  CoverBand(0, helper ? middle - 1 : height_ - 1, rows_);
  if (helper) helper->join();
  rows_ = {std::min(rows_.first, upper.first), std::max(rows_.second, upper.second)};
}

void PointSplat::Add(const scene::PointSet& points, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P) {
  using Style = scene::PointSet::Style;
  const std::size_t n = std::min(points.positions.size(), points.colours.size());
  const Eigen::Matrix4f MV = V.cast<float>(), Pf = P.cast<float>();
  const Eigen::Matrix4f MVP = Pf * MV;
  const float half_width = 0.5f * static_cast<float>(width_), half_height = 0.5f * static_cast<float>(height_);
  // window x, y and depth of a clip-space position
  const auto window = [&](const Eigen::Vector4f& clip) {
    return Eigen::Vector3f((clip.x() / clip.w() + 1.f) * half_width, (clip.y() / clip.w() + 1.f) * half_height,
                           0.5f * (clip.z() / clip.w() + 1.f));
  };
  const int shape = points.style == Style::kSquares ? 1 : points.style == Style::kSpheres ? 2 : 0;
  const float half = 0.5f * points.size.x();   // pixels for Points, metres for the squares
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector4f rgba = points.colours[i].unaryExpr(&Channel8);   // the 8-bit vertex colour
    const Eigen::Vector4f p(points.positions[i].x(), points.positions[i].y(), points.positions[i].z(), 1.f);
    if (points.style == Style::kPoints) {
      // a GL point: clipped by its centre, a square of point_size pixels (at least one)
      const Eigen::Vector4f clip = MVP * p;
      if (!(std::abs(clip.x()) <= clip.w() && std::abs(clip.y()) <= clip.w() && std::abs(clip.z()) <= clip.w())) continue;
      const Eigen::Vector3f w = window(clip);
      const float h = std::max(half, 0.5f);
      Keep(w.x() - h, w.x() + h, w.y() - h, w.y() + h, w.z(), rgba, 0);
    } else {
      // a camera-facing square: corners moved from the centre in the image plane, clipped near/far
      const Eigen::Vector4f centre = MV * p;
      const Eigen::Vector4f clip = Pf * centre;
      if (!(std::abs(clip.z()) <= clip.w())) continue;
      const Eigen::Vector3f low = window(Pf * (centre + Eigen::Vector4f(-half, -half, 0, 0)));
      const Eigen::Vector3f high = window(Pf * (centre + Eigen::Vector4f(half, half, 0, 0)));
      Keep(low.x(), high.x(), low.y(), high.y(), window(clip).z(), rgba, shape);
    }
  }
}

}  // namespace urdfsnap::gl
