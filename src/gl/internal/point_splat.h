// The opaque camera-facing point styles (Points, Squares, Flat Squares, Spheres) drawn on the CPU
// into a per-sample colour and depth image, which PointSetDrawing composites into the frame with
// one draw per sample writing gl_FragDepth (so the robot still hides points behind it and points
// hide the robot). llvmpipe spends ~0.6 us of rasteriser time per point primitive: 100k points
// cost 75-95 ms of CPU a frame through GL and ~25 this way (docs/point-clouds.md). Each sample is
// covered exactly as llvmpipe covers it (sample inside the square; the square's colour and shape
// evaluated at the pixel centre, as a multisampled fragment shader runs once per pixel), so the
// picture is the GL one. The squares are sorted by row before they are covered, so the image is
// walked row by row rather than at random (a Points frame went from ~35 to ~29 ms of CPU). No GL
// here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "scene/scene.h"

namespace urdfsnap::gl {

class PointSplat {
 public:
  // Whether an opaque set of `points` can be splatted: a camera-facing style (not Boxes).
  static bool Splattable(const scene::PointSet& points) { return points.style != scene::PointSet::Style::kBoxes; }
  // Fewer opaque camera-facing points in a frame than this are drawn by GL: the splat's cost per
  // frame whatever it holds (clearing its image, uploading and compositing it per sample: ~4 ms of
  // CPU at 640x480 with 4x multisampling) is more than GL's ~0.6 us a point below some 5,000 points
  // (points bench, paired: 2,000 Points 11.1 ms splatted, 7.1 by GL; 20,000 14.2 and 20.8).
  // A marker's points and sphere lists are usually few.
  static constexpr std::size_t kFewestPoints = 4096;

  // Empties the image for `width` x `height` pixels, each with the given sample positions (pixel
  // units within a pixel, GL window coordinates: y up; {0.5, 0.5} without multisampling).
  void Clear(int width, int height, const std::vector<Eigen::Vector2f>& samples);
  // Adds the squares of `points` seen through view `V` and projection `P`.
  void Add(const scene::PointSet& points, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P);
  // Covers the samples of every square added since Clear: the nearest wins, on a tie the later
  // (GL_LEQUAL). With many squares the rows are split in two bands, one covered by another thread.
  void Cover();
  static constexpr std::size_t kSquaresPerThread = 4096;   // fewer squares: one thread

  bool empty() const { return rows_.first > rows_.second; }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return static_cast<int>(samples_.size()); }
  // One sample: its depth in [0, 1] as GL's depth range maps it (kEmpty where nothing is) and its
  // colour, rgba8 in memory order, side by side so that a depth test and its write share a line.
  struct Texel {
    float depth;
    std::uint32_t colour;
  };
  // The image: rows bottom first (GL's order), each pixel's samples side by side (sample s of pixel
  // (x, y) at (y * width + x) * samples + s).
  const std::vector<Texel>& texels() const { return texels_; }
  static constexpr float kEmpty = 2.f;
  // The rows [first, second] that hold anything (first > second when empty).
  std::pair<int, int> rows() const { return rows_; }

 private:
  // A point's square in window coordinates, [x0, x1) x [y0, y1) at `depth`; shape 0 flat, 1
  // outlined, 2 shaded disc (shaders/point.frag); its rows and columns of pixels that may hold a
  // covered sample.
  struct Square {
    float x0, x1, y0, y1, depth;
    Eigen::Vector4f rgba;
    int shape;
    int px0, px1, py0, py1;
  };
  // Keeps the square, snapped as llvmpipe snaps, unless it covers no pixel.
  void Keep(float x0, float x1, float y0, float y1, float depth, const Eigen::Vector4f& rgba, int shape);
  // Covers the samples of `square` in rows [first, last]; whether it covered any.
  bool CoverSquare(const Square& square, int first, int last);
  // Covers the rows [first, last] with every sorted square that reaches them, widening `rows` to
  // the rows drawn.
  void CoverBand(int first, int last, std::pair<int, int>& rows);
  int width_ = 0, height_ = 0;
  std::vector<Square> squares_, sorted_;
  std::vector<Eigen::Vector2f> samples_;
  Eigen::Vector2f sample_min_, sample_max_;   // their extent within a pixel
  std::vector<Texel> texels_;
  std::pair<int, int> rows_{0, -1};
};

}  // namespace urdfsnap::gl
