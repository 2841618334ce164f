// OpenCV's radial-tangential distortion, forward and by fixed-point inversion.
#include "camera/distortion.h"

#include <algorithm>
#include <cmath>

namespace urdfsnap::camera {

bool Distortion::Any() const {
  return std::any_of(k.begin(), k.end(), [](double c) { return c != 0; });
}

std::optional<Distortion> MakeDistortion(const std::string& model, const std::vector<double>& d,
                                         std::string& why) {
  Distortion distortion;
  if (d.empty() && (model.empty() || model == "none" || model == "plumb_bob" || model == "rational_polynomial")) {
    return distortion;
  }
  size_t most = 0;
  if (model == "plumb_bob") {
    if (d.size() != 4 && d.size() != 5) {
      why = "plumb_bob takes 5 coefficients (k1, k2, p1, p2, k3), got " + std::to_string(d.size());
      return std::nullopt;
    }
    most = 5;
  } else if (model == "rational_polynomial") {
    if (d.size() != 8) {
      why = "rational_polynomial takes 8 coefficients (k1, k2, p1, p2, k3, k4, k5, k6), got " +
            std::to_string(d.size());
      return std::nullopt;
    }
    most = 8;
  } else {
    why = "distortion model '" + model + "' is not supported (plumb_bob, rational_polynomial)";
    return std::nullopt;
  }
  std::copy_n(d.begin(), std::min(d.size(), most), distortion.k.begin());
  return distortion;
}

namespace {

// 1/radial factor and the tangential offset at an ideal point, as OpenCV's undistortPoints
// computes them (icdist, deltaX, deltaY).
struct Terms {
  double inverse_radial;
  Eigen::Vector2d tangential;
};

Terms TermsAt(const std::array<double, 8>& k, const Eigen::Vector2d& p) {
  const double x = p.x(), y = p.y();
  const double r2 = x * x + y * y;
  const double numerator = 1 + ((k[4] * r2 + k[1]) * r2 + k[0]) * r2;
  const double denominator = 1 + ((k[7] * r2 + k[6]) * r2 + k[5]) * r2;
  return {denominator / numerator,
          {2 * k[2] * x * y + k[3] * (r2 + 2 * x * x), k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y}};
}

}  // namespace

Eigen::Vector2d Distort(const Distortion& d, const Eigen::Vector2d& ideal) {
  const Terms t = TermsAt(d.k, ideal);
  return ideal / t.inverse_radial + t.tangential;
}

std::optional<Eigen::Vector2d> Undistort(const Distortion& d, const Eigen::Vector2d& distorted) {
  Eigen::Vector2d p = distorted;
  for (int step = 0; step < 100; ++step) {
    const Terms t = TermsAt(d.k, p);
    // OpenCV stops where the radial factor turns negative: the polynomial has folded over
    if (!(t.inverse_radial > 0) || !std::isfinite(t.inverse_radial)) return std::nullopt;
    const Eigen::Vector2d next = (distorted - t.tangential) * t.inverse_radial;
    const double moved = (next - p).lpNorm<Eigen::Infinity>();
    p = next;
    if (moved < 1e-12) break;
  }
  if (!p.allFinite() || (Distort(d, p) - distorted).lpNorm<Eigen::Infinity>() > 1e-9) return std::nullopt;
  return p;
}

}  // namespace urdfsnap::camera
