// Pinhole projection and its OpenGL matrix.
#include "camera/pinhole.h"

#include <cmath>

namespace urdfsnap::camera {

Eigen::Vector2d ToPixel(const Intrinsics& k, const Eigen::Vector2d& normalised) {
  return {k.fx * normalised.x() + k.cx, k.fy * normalised.y() + k.cy};
}

Eigen::Vector2d FromPixel(const Intrinsics& k, const Eigen::Vector2d& pixel) {
  return {(pixel.x() - k.cx) / k.fx, (pixel.y() - k.cy) / k.fy};
}

Intrinsics CentredIntrinsics(double fov_y, int width, int height) {
  const double f = height / (2 * std::tan(fov_y / 2));
  return {f, f, (width - 1) / 2.0, (height - 1) / 2.0};
}

Eigen::Matrix4d GlProjection(const Intrinsics& k, int width, int height, double near, double far) {
  // with a GL eye point (xg, yg, zg) = (x, −y, −z) of the optical point (x, y, z), clip w = z and
  // x_ndc = 2(u + 0.5)/width − 1, y_ndc = 1 − 2(v + 0.5)/height: solving for the rows gives
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  P(0, 0) = 2 * k.fx / width;
  P(0, 2) = 1 - 2 * (k.cx + 0.5) / width;
  P(1, 1) = 2 * k.fy / height;
  P(1, 2) = 2 * (k.cy + 0.5) / height - 1;
  P(2, 2) = (far + near) / (near - far);
  P(2, 3) = 2 * far * near / (near - far);
  P(3, 2) = -1;
  return P;
}

}  // namespace urdfsnap::camera
