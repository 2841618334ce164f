// The convex hull of points in a plane: what --fit keeps of a robot's vertices seen along one image
// axis, since only the hull's corners can touch the edges of the frame.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace urdfsnap::scene {

// The corners of the convex hull of `points`, counter-clockwise, without collinear points or
// repeats (one point for a single distinct point, two for points on a line). Points strictly
// inside the octagon of the extremes in eight directions are dropped before sorting, so a dense
// mesh costs little more than one pass.
std::vector<Eigen::Vector2d> ConvexHull2d(std::vector<Eigen::Vector2d> points);

}  // namespace urdfsnap::scene
