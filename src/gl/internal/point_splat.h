// The opaque camera-facing point styles (Points, Squares, Flat Squares, Spheres) drawn on the CPU
// into a per-sample colour and depth image, which PointSetDrawing composites into the frame with
// one draw per sample writing gl_FragDepth (so the robot still hides points behind it and points
// hide the robot). llvmpipe spends ~0.6 us of rasteriser time per point primitive: 100k points
// cost 75-95 ms of CPU a frame through GL and ~14 this way (docs/point-clouds.md). Each sample is
// covered exactly as llvmpipe covers it (sample inside the square; the square's colour and shape
// evaluated at the pixel centre, as a multisampled fragment shader runs once per pixel), so the
// picture is the GL one but where two points' depths tie or nearly tie. The image is covered
// tile by tile, each tile's samples in the L1 cache, rather than point by point over the whole
// image. No GL here.
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
  // A frame's opaque camera-facing points whose GlCost is below this are drawn by GL: the splat's
  // cost whatever it holds (emptying, writing out and compositing per sample the tiles the points
  // reach: ~8 ms of CPU for a cloud around mrm at 640x480 with 4x multisampling, when this was
  // measured) is more than GL's ~1.2 us a square below some 5,000 squares. A marker's points and
  // sphere lists are usually few.
  static constexpr std::size_t kFewestPoints = 4096;
  // What GL would spend on drawing `points`, in camera-facing squares: a GL point (Points) costs
  // llvmpipe about a third of a square's two triangles (points bench, CPU ms per frame with mrm,
  // paired: Points by GL 8.0 / 13.4 / 15.5 at 8,000 / 12,000 / 16,000 points, splatted 13.0 /
  // 14.1 / 14.5; Flat Squares at 8,000 by GL 14.1, splatted 13.3).
  static std::size_t GlCost(const scene::PointSet& points) {
    return points.style == scene::PointSet::Style::kPoints ? points.positions.size() / 3 : points.positions.size();
  }

  // Starts a frame of `width` x `height` pixels, each with the given sample positions (pixel
  // units within a pixel, GL window coordinates: y up; {0.5, 0.5} without multisampling).
  void Clear(int width, int height, const std::vector<Eigen::Vector2f>& samples);
  // Adds the squares of `points` seen through view `V` and projection `P`.
  void Add(const scene::PointSet& points, const Eigen::Matrix4d& V, const Eigen::Matrix4d& P);
  // Covers the samples of every square added since Clear: the nearest wins, on a tie the later
  // (GL_LEQUAL). The image is cut into tiles of kTileSize x kTileSize pixels whose samples fit in
  // a core's L1 cache; each tile reached by a square is emptied and covered with its squares in
  // the order they were added, and with many squares the two threads take tiles in turn (a tile
  // is written by one thread only, so the image is the same as from one thread). Given `texels`
  // (TexelWords() words), each drawn tile is also written there as the composite reads it: the
  // tile's samples at texels + 2 * kPlane * samples() * tile, for each sample in turn kTileSize
  // rows (bottom first) of kTileSize (depth's float bits, colour) pairs.
  void Cover(std::uint32_t* texels = nullptr);
  std::size_t TexelWords() const { return TexelWords(width_, height_, samples()); }
  // The same for a frame of `width` x `height` pixels of `samples` samples.
  static std::size_t TexelWords(int width, int height, int samples) {
    const auto tiles = [](int pixels) { return static_cast<std::size_t>((pixels + kTileSize - 1) / kTileSize); };
    return tiles(width) * tiles(height) * 2 * kPlane * static_cast<std::size_t>(samples);
  }
  int tiles_x() const { return tiles_x_; }
  static constexpr int kTileSize = 32;   // a power of two (the composite shader shifts by it)
  static constexpr std::size_t kSquaresPerThread = 4096;   // fewer squares: one thread

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return static_cast<int>(samples_.size()); }
  // One sample: its depth in [0, 1] as GL's depth range maps it (kEmpty where nothing is) and its
  // colour, rgba8 in memory order.
  struct Texel {
    float depth;
    std::uint32_t colour;
  };
  static constexpr float kEmpty = 2.f;
  // A tile's pixels [x0, x1) x [y0, y1) (the last column and row of tiles end at the image's edge).
  struct Tile {
    int x0, y0, x1, y1;
  };
  // The tiles that squares reached (whose pixels may hold a covered sample), in the image's order
  // (rows of tiles bottom first); the rest of the image is empty.
  const std::vector<int>& drawn() const { return drawn_; }
  bool empty() const { return drawn_.empty(); }
  Tile TileAt(int tile) const;
  // The words of a tile's samples: a depth and a colour for each sample of each pixel.
  std::size_t TileWords() const { return 2 * kPlane * samples_.size(); }
  static constexpr std::size_t kPlane = static_cast<std::size_t>(kTileSize) * kTileSize;
  // Sample s of pixel (x, y) (kEmpty outside the tiles drawn).
  Texel At(int x, int y, int s) const;

 private:
  // A point's square in window coordinates, [x0, x1) x [y0, y1) at `depth`; its 8-bit rgba; its
  // place in the order squares were added; and, packed in `reach`, the first tile it reaches (its
  // index), whether it reaches the next column and the next row of tiles too, and its shape (0
  // flat, 1 outlined, 2 shaded disc: shaders/point.frag). 32 bytes, copied once per tile reached.
  struct Square {
    float x0, x1, y0, y1, depth;
    std::uint32_t rgba8;
    std::uint32_t order;
    std::uint32_t reach;
    static constexpr int kShapeShift = 30, kWide = 1 << 28, kHigh = 1 << 29, kTileMask = kWide - 1;
    int shape() const { return static_cast<int>(reach >> kShapeShift); }
    int tile() const { return static_cast<int>(reach & kTileMask); }
  };
  // The pixels whose samples `square` may cover: columns [px0, px1], rows [py0, py1], within the image.
  struct Pixels {
    int px0, px1, py0, py1;
  };
  Pixels Reach(float x0, float x1, float y0, float y1) const;
  // Squares kept by one thread from a run of one set's points, as added: those reaching at most 2 x
  // 2 tiles, those reaching more (kept once: Bin), and how many reach each tile t (counts[t]; not
  // the big ones); then (Bin) where in binned_ its next square for tile t goes (next[t]).
  struct Kept {
    std::vector<Square> squares, big;
    std::vector<std::uint32_t> counts, next;
  };
  // Takes an emptied Kept after those taken since Clear.
  void NextKept();
  // Keeps into `kept` the squares of points [first, last) of `points`, the i-th the order-th added
  // (order = first_order + i).
  void Project(const scene::PointSet& points, const Eigen::Matrix4f& MV, const Eigen::Matrix4f& P, std::size_t first,
               std::size_t last, std::uint32_t first_order, Kept& kept) const;
  // Keeps the square, its corners snapped as llvmpipe snaps them, unless it covers no pixel, and
  // counts it in the tiles it reaches.
  void Keep(Kept& kept, const Square& square) const;
  // Keeps a GL point of `size` pixels (at least one) centred at window (x, y), as lp_setup_point
  // places it: its centre snapped, then moved out by half the snapped size.
  void KeepPoint(Kept& kept, float x, float y, float size, float depth, std::uint32_t rgba8, std::uint32_t order) const;
  // Keeps a square already snapped.
  void KeepSnapped(Kept& kept, Square square) const;
  // Keeps a square already snapped whose samples may cover `pixels` (Reach).
  void KeepReaching(Kept& kept, Square square, const Pixels& pixels) const;
  // Sorts copies of the squares by the tiles they reach, in the order they were added (big ones
  // aside), and lists the tiles reached; with many squares, each thread copies some Kepts.
  void Bin();
  // Runs work(0) on this thread and work(1) on a second one if `two` (and a thread can be had;
  // else after work(0)).
  template <typename Work>
  static void OnTwoThreads(bool two, const Work& work);
  // Empties tile `tile`, covers it with its squares and, given `texels`, writes it there (Cover).
  void CoverTile(int tile, std::uint32_t* texels);
  // Covers the samples of `square` within `tile`, whose planes start at `planes`.
  void CoverSquare(const Square& square, const Tile& tile, std::uint32_t* planes) const;
  int width_ = 0, height_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  // the squares kept since Clear, in the order added (kept_[0, kept_used_); a set's points in
  // one Kept or, for a big set, two, one from each thread); the order the next added takes
  std::vector<Kept> kept_;
  std::size_t kept_used_ = 0;
  std::uint32_t next_order_ = 0;
  // by tile (Bin): tile t's in binned_[tile_starts_[t]..[t + 1]); those reaching more than 2 x 2
  // tiles, in the order added
  std::vector<Square> binned_, big_;
  std::vector<std::uint32_t> tile_starts_;
  // Keeps from every thread so far, squares and big ones
  std::size_t KeptSquares() const;
  std::vector<Eigen::Vector2f> samples_;
  Eigen::Vector2f sample_min_, sample_max_;   // their extent within a pixel
  bool fixed_samples_ = false;                 // whether they lie on the 1/256-pixel grid, and then
  Eigen::Vector2i fixed_sample_min_, fixed_sample_max_;   // their extent in 1/256 pixel
  std::vector<float> sample_x_, sample_y_;    // their x and y, as many as a multiple of four
  // tile by tile (TileWords): for each sample in turn its plane of depths' float bits, then its
  // plane of colours, kTileSize rows (bottom first) of kTileSize (those past the image's edge
  // unused); a row of one sample's depths or colours is contiguous, four columns one vector
  std::vector<std::uint32_t> planes_;
  std::vector<int> drawn_;
};

}  // namespace urdfsnap::gl
