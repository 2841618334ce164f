// The points of a 3-D set that can be corners of its convex hull seen along some direction: what a
// turntable's --fit keeps of a robot's vertices once, instead of hulling every vertex at every yaw.
// A projection's 2-D hull corners are projections of 3-D hull corners, so a point well inside the
// 3-D hull never is one.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace urdfsnap::scene {

// For each of `points`: false when the point is inside the convex hull of the set by more than
// 1e-9 of the set's size (its bounding box's diagonal plus its largest coordinate: far beyond
// rounding, in any projection); true otherwise (the hull's corners and every point nearer its
// faces than that). Every point is kept (all true) when a coordinate is not finite or the points
// span no volume.
std::vector<bool> HullCandidates(const std::vector<Eigen::Vector3d>& points);

}  // namespace urdfsnap::scene
