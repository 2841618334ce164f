// HullCandidates through Qhull (Debian's libqhull-dev, its reentrant library: a robust 3-D
// hull of tens of thousands of points in milliseconds, where a hand-written one would have to
// earn that robustness): the hull's vertices and the points less than the depth below the face
// Qhull found nearest (its "Qc Qi" keep every other point with that face).
#include "scene/hull_candidates.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

#include <libqhull_r/qhull_ra.h>

namespace urdfsnap::scene {

namespace {

// How deep inside a point must be to be dropped, as a fraction of the set's size.
constexpr double kDepth = 1e-9;

// Qhull's state for one hull, freed however the hull ends; its messages go nowhere (a flat set
// is not an error here: every point is then kept).
class Qhull {
 public:
  Qhull() : messages_(std::fopen("/dev/null", "w")) { qh_zero(&qh_, messages_); }
  ~Qhull() {
    qh_freeqhull(&qh_, !qh_ALL);
    int long_left = 0, total_left = 0;
    qh_memfreeshort(&qh_, &long_left, &total_left);
    if (messages_) std::fclose(messages_);
  }
  Qhull(const Qhull&) = delete;
  Qhull& operator=(const Qhull&) = delete;

  // Hulls `coordinates` (x, y, z of each point) with Qhull's `options`; false when Qhull fails.
  bool Run(std::vector<coordT>& coordinates, const std::string& options) {
    std::string command = "qhull " + options;
    return qh_new_qhull(&qh_, 3, static_cast<int>(coordinates.size() / 3), coordinates.data(), False,
                        command.data(), nullptr, messages_) == 0;
  }

  // Marks in `kept` every vertex of the hull and every point Qhull kept with a face (with "Qc Qi":
  // all the others, each with the face it found nearest) less than `depth` below that face.
  void MarkKept(double depth, std::vector<bool>& kept) {
    qhT* qh = &qh_;
    vertexT* vertex;
    FORALLvertices kept[qh_pointid(qh, vertex->point)] = true;
    facetT* facet;
    pointT *point, **pointp;
    FORALLfacets {
      FOREACHpoint_(facet->coplanarset) {
        double distance = 0;
        qh_distplane(qh, point, facet, &distance);
        if (distance > -depth) kept[qh_pointid(qh, point)] = true;
      }
    }
  }

 private:
  qhT qh_;
  FILE* messages_;
};

}  // namespace

std::vector<bool> HullCandidates(const std::vector<Eigen::Vector3d>& points) {
  std::vector<bool> all(points.size(), true);
  if (points.size() < 5 || !std::all_of(points.begin(), points.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); })) {
    return all;
  }
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& p : points) box.extend(p);
  const double size = box.diagonal().norm() + std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  std::vector<coordT> coordinates;
  coordinates.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points) coordinates.insert(coordinates.end(), {p.x(), p.y(), p.z()});
  Qhull qhull;
  if (!qhull.Run(coordinates, "Qc Qi")) return all;
  std::vector<bool> kept(points.size(), false);
  qhull.MarkKept(kDepth * size, kept);
  return kept;
}

}  // namespace urdfsnap::scene
