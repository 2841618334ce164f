// The pinhole camera in OpenCV's and ROS's pixel convention (pixel centres at integer coordinates,
// u = fx·x/z + cx, v = fy·y/z + cy with x right, y down, z forward), and the OpenGL projection
// matrix that puts every point on exactly that pixel.
#pragma once

#include <Eigen/Core>

namespace urdfsnap::camera {

// Focal lengths and principal point in pixels (a CameraInfo's K or the left 3x3 of P). Skew is
// not modelled, as OpenCV's projectPoints ignores K's (0, 1) entry.
struct Intrinsics {
  double fx = 0;
  double fy = 0;
  double cx = 0;
  double cy = 0;
};

// The pixel (u, v) of the normalised image point (x/z, y/z).
Eigen::Vector2d ToPixel(const Intrinsics& k, const Eigen::Vector2d& normalised);

// The normalised image point (x/z, y/z) of pixel (u, v).
Eigen::Vector2d FromPixel(const Intrinsics& k, const Eigen::Vector2d& pixel);

// The intrinsics of a camera with vertical field of view `fov_y` (rad) and square pixels whose
// principal point is the image centre ((width − 1)/2, (height − 1)/2 in OpenCV's convention), as
// RViz's orbit view draws.
Intrinsics CentredIntrinsics(double fov_y, int width, int height);

// The OpenGL projection matrix for a camera looking down −Z with +Y up (the optical frame turned
// by 180° about x) that maps every point to the pixel ToPixel gives it in a width x height image
// read top row first: normalised device x = −1 is the left edge of pixel column 0 (u = −0.5) and
// y = +1 the top edge of row 0 (v = −0.5). near and far are the clipping distances along the
// optical axis in metres (0 < near < far); depth is hyperbolic as in any GL perspective matrix.
Eigen::Matrix4d GlProjection(const Intrinsics& k, int width, int height, double near, double far);

}  // namespace urdfsnap::camera
