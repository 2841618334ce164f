// CoverageCull: per small instance, its vertices to window coordinates on the CPU and each
// triangle's facing and sample coverage judged with a margin that only ever keeps too much.
#include "gl/internal/coverage_cull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Geometry>

namespace urdfsnap::gl {

namespace {

// An instance is culled when its triangles are at least this many per pixel of the square around
// its bounding sphere on screen: then most of them cover no sample. A 0.1 m sphere in RViz's
// default view is 720 triangles over a ~36-pixel square (~20 in each); culled it keeps ~120 and
// costs ~4 ms less per 91 spheres. A 0.1 m cylinder (160 over ~60, 2.6 a pixel) keeps ~70 of its
// triangles, but dropping its back faces (which llvmpipe drops cheaply itself) and a few slivers
// saved nothing measurable, so it is drawn whole (docs/displays.md, "Fidelity and speed").
constexpr double kTrianglesPerPixel = 4;

// How far a window-space coordinate llvmpipe computes may lie from ours beyond the float error
// bound (Margin): its snapping to 1/256 pixel (off by half that at most), twice over.
constexpr double kSnapSlack = 1.0 / 256;

// A triangle whose box (with its slack) is this many square pixels or more is kept without looking
// for a sample it covers: it most likely does, and looking costs more the larger it is.
constexpr float kLargestTested = 16;

// A bound on the relative error of a float dot product of four terms (as lit.vert's
// model_view_projection * position, computed by llvmpipe and again by us): 2^-20 is ~8 float
// ulps, four times the worst case of four roundings.
constexpr double kFloatError = 1.0 / (1 << 20);

// An instance whose positions may be off by more than this many pixels is drawn whole.
constexpr double kMostError = 0.25;

// Nor is one whose clip coordinates could come near float's range (3.4e38).
constexpr double kLargestTerms = 1e30;

// The largest integer at most `x` and the least at least `x` (window coordinates, well within an
// int), without a call to floorf or ceilf (x86-64 without SSE 4.1 has no rounding instruction).
int Floor(float x) {
  const int truncated = static_cast<int>(x);
  return truncated - (x < static_cast<float>(truncated));
}
int Ceil(float x) {
  const int truncated = static_cast<int>(x);
  return truncated + (x > static_cast<float>(truncated));
}

}  // namespace

CoverageCull::CoverageCull(int width, int height, std::vector<Eigen::Vector2f> samples)
    : width_(width), height_(height), samples_(std::move(samples)) {
  // lanes past the pattern's samples lie at infinity, in no box
  sample_x_.setConstant(std::numeric_limits<float>::infinity());
  sample_y_.setConstant(std::numeric_limits<float>::infinity());
  for (std::size_t s = 0; s < std::min<std::size_t>(samples_.size(), 4); ++s) {
    sample_x_[static_cast<Eigen::Index>(s)] = samples_[s].x();
    sample_y_[static_cast<Eigen::Index>(s)] = samples_[s].y();
  }
}

double CoverageCull::Margin(const Eigen::Matrix4d& mvp, const Eigen::Vector3d& centre, double radius,
                            int triangles) const {
  // wholly inside the six planes (-w <= x, y, z <= w) by more than the radius: nothing clipped
  const Eigen::Vector4d c = centre.homogeneous();
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {1.0, -1.0}) {
      const Eigen::Vector4d plane = mvp.row(3).transpose() + side * mvp.row(axis).transpose();
      if (!(plane.dot(c) > radius * plane.head<3>().norm())) return -1;
    }
  }
  const double w_min = mvp.row(3).dot(c) - radius * mvp.row(3).head<3>().norm();
  if (!(w_min > 0)) return -1;
  // the square around the sphere on screen, at its nearest depth
  const double half_x = radius * mvp.row(0).head<3>().norm() / w_min * width_ / 2;
  const double half_y = radius * mvp.row(1).head<3>().norm() / w_min * height_ / 2;
  if (triangles < kTrianglesPerPixel * 4 * half_x * half_y) return -1;
  // x, y and w are each off by at most kFloatError times the sum of their terms' sizes, so x / w
  // (within [-1, 1]) by at most twice that over w
  const Eigen::Vector4d extent((centre.cwiseAbs().array() + radius).matrix().homogeneous());
  double terms = 0;
  for (const int row : {0, 1, 3}) terms = std::max(terms, mvp.row(row).cwiseAbs().dot(extent));
  if (!(terms < kLargestTerms)) return -1;   // so that the float clip coordinates stay finite
  const double error = 2 * kFloatError * terms / w_min * std::max(width_, height_) / 2;
  return error <= kMostError ? error : -1;
}

bool CoverageCull::Drawn(const Eigen::Vector2f& a, const Eigen::Vector2f& b, const Eigen::Vector2f& c,
                         float slack) const {
  // twice the signed area, front faces positive; with each corner off by `slack` pixels it is
  // off by at most 2 slack (|b - a| + |c - a|, 1-norms) + 4 slack^2, doubled here for safety
  const float sign = clockwise_ ? -1.f : 1.f;
  const Eigen::Vector2f e1 = b - a, e2 = c - a;
  const float area = sign * (e1.x() * e2.y() - e1.y() * e2.x());
  const float area_slack = 4 * slack * (e1.lpNorm<1>() + e2.lpNorm<1>()) + 16 * slack * slack;
  if (area < -area_slack) return false;   // back-facing: GL culls it
  // else GL may draw it: then it faces front, and its edge functions are those below
  const Eigen::Vector2f lo = a.cwiseMin(b).cwiseMin(c).array() - slack;
  const Eigen::Vector2f hi = a.cwiseMax(b).cwiseMax(c).array() + slack;
  const Eigen::Vector2f box = hi - lo;
  if (box.x() * box.y() >= kLargestTested) return true;
  // the samples in the box; under a pixel each way it holds at most one of each of the pattern's
  // (all four at once, as vectors), in the box's first column (row) when its offset is past the
  // box's left (lower) edge's, else in the next
  const bool small = box.x() < 1 && box.y() < 1 && samples_.size() <= 4;
  Eigen::Array4f xs, ys;
  Eigen::Array4i in_box;
  if (small) {
    const auto column = static_cast<float>(Floor(lo.x())), row = static_cast<float>(Floor(lo.y()));
    const float left = lo.x() - column, lower = lo.y() - row;
    xs = column + sample_x_ + (sample_x_ < left).cast<float>();
    ys = row + sample_y_ + (sample_y_ < lower).cast<float>();
    in_box = ((xs <= hi.x()) && (ys <= hi.y())).cast<int>();
    if (!in_box.any()) return false;
  }
  // each edge's function sign (edge x (p - from)), positive inside; with the corners and so the
  // edge off by `slack` it is off by at most 2 slack (|edge| + |p - from|) + 4 slack^2, and
  // |p - from| is within the box's width plus height for a sample p in the box
  struct Edge {
    Eigen::Vector2f from, along;
    float tolerance;
  };
  Edge edges[3] = {{a, b - a, 0}, {b, c - b, 0}, {c, a - c, 0}};
  for (Edge& edge : edges) {
    edge.along *= sign;
    edge.tolerance = -(2 * slack * (edge.along.lpNorm<1>() + box.x() + box.y()) + 4 * slack * slack);
  }
  const auto covers = [&edges](float x, float y) {
    bool inside = true;
    for (const Edge& edge : edges) {
      inside = inside && edge.along.x() * (y - edge.from.y()) - edge.along.y() * (x - edge.from.x()) >= edge.tolerance;
    }
    return inside;
  };
  if (small) {
    for (int s = 0; s < 4; ++s) {
      if (in_box[s] && covers(xs[s], ys[s])) return true;
    }
    return false;
  }
  for (const Eigen::Vector2f& s : samples_) {
    const int column_lo = Ceil(lo.x() - s.x()), column_hi = Floor(hi.x() - s.x());
    for (int row = Ceil(lo.y() - s.y()); row <= Floor(hi.y() - s.y()); ++row) {
      for (int column = column_lo; column <= column_hi; ++column) {
        if (covers(static_cast<float>(column) + s.x(), static_cast<float>(row) + s.y())) return true;
      }
    }
  }
  return false;
}

bool CoverageCull::Cull(const geometry::TriangleMesh& mesh, const Eigen::Vector3d& centre, double radius,
                        bool clockwise, const std::vector<MeshInstance>& instances,
                        std::vector<std::uint32_t>& indices, std::vector<InstanceTriangles>& commands) {
  indices.clear();
  commands.clear();
  // a mesh made through the C++ API may name vertices it lacks: GL's business, not ours
  const std::size_t vertices = mesh.positions.size();
  if (std::any_of(mesh.indices.begin(), mesh.indices.end(), [&](std::uint32_t v) { return v >= vertices; })) {
    return false;
  }
  const auto all = static_cast<std::uint32_t>(mesh.indices.size());
  std::uint32_t whole_first = 0;   // where the mesh's own indices are in `indices`, once needed
  bool whole_added = false, culled = false;
  clockwise_ = clockwise;
  window_.resize(mesh.positions.size());
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const Eigen::Map<const Eigen::Matrix4f> mvp(instances[i].model_view_projection);
    InstanceTriangles command;
    command.base_instance = static_cast<std::uint32_t>(i);
    const double error = Margin(mvp.cast<double>(), centre, radius, mesh.triangle_count());
    if (error < 0) {
      if (!whole_added) {
        whole_first = static_cast<std::uint32_t>(indices.size());
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
        whole_added = true;
      }
      command.first_index = whole_first;
      command.count = all;
      commands.push_back(command);
      continue;
    }
    culled = true;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const Eigen::Vector4f clip = mvp * mesh.positions[v].homogeneous();
      window_[v] = {(clip.x() / clip.w() * 0.5f + 0.5f) * static_cast<float>(width_),
                    (clip.y() / clip.w() * 0.5f + 0.5f) * static_cast<float>(height_)};
    }
    const auto slack = static_cast<float>(error + kSnapSlack);
    command.first_index = static_cast<std::uint32_t>(indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      if (Drawn(window_[mesh.indices[t]], window_[mesh.indices[t + 1]], window_[mesh.indices[t + 2]], slack)) {
        indices.insert(indices.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
      }
    }
    command.count = static_cast<std::uint32_t>(indices.size()) - command.first_index;
    if (command.count > 0) commands.push_back(command);
  }
  if (!culled) {
    indices.clear();
    commands.clear();
  }
  return culled;
}

}  // namespace urdfsnap::gl
