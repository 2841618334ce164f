// Lens distortion as OpenCV defines it (calib3d projectPoints; imgproc undistortPoints), for the two
// models ROS's camera_calibration writes: plumb_bob (k1, k2, p1, p2, k3) and rational_polynomial
// (k1, k2, p1, p2, k3, k4, k5, k6). Thin-prism and tilt terms, which ROS never writes, are not
// modelled.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace urdfsnap::camera {

struct Distortion {
  // OpenCV's order k1, k2, p1, p2, k3, k4, k5, k6; missing ones are 0, all 0 is no distortion.
  std::array<double, 8> k{};

  // Whether any coefficient is non-zero.
  bool Any() const;
};

// The coefficients of `model` ("plumb_bob", "rational_polynomial"; "" or "none" for none) from
// `d` as a CameraInfo lists them. plumb_bob takes 4 or 5 numbers, rational_polynomial 8; an empty
// `d` is no distortion. Returns nullopt with `why` filled for an unknown model or a wrong count.
std::optional<Distortion> MakeDistortion(const std::string& model, const std::vector<double>& d,
                                         std::string& why);

// The distorted normalised point of the ideal normalised point (x/z, y/z): OpenCV's
// x' = x·(1 + k1 r² + k2 r⁴ + k3 r⁶)/(1 + k4 r² + k5 r⁴ + k6 r⁶) + 2 p1 x y + p2 (r² + 2x²), and
// y' likewise with p1 (r² + 2y²) + 2 p2 x y.
Eigen::Vector2d Distort(const Distortion& d, const Eigen::Vector2d& ideal);

// The ideal normalised point whose distorted image is `distorted`, by OpenCV's fixed-point
// iteration (undistortPoints) run until it moves less than 1e-12 or 100 steps. nullopt where it
// does not converge to a point that distorts back within 1e-9 (outside the lens's valid field,
// where the polynomial folds over).
std::optional<Eigen::Vector2d> Undistort(const Distortion& d, const Eigen::Vector2d& distorted);

}  // namespace urdfsnap::camera
