// Grid line generation, as RViz's Grid::create does for the "Lines" style with no normal cells.
#include "scene/grid.h"

#include <numbers>

#include <Eigen/Geometry>

namespace urdfsnap::scene {

LineSet MakeGrid(const GridOptions& options) {
  LineSet grid;
  grid.rgba << options.colour, options.alpha;
  const int n = options.plane_cell_count;
  const float extent = static_cast<float>(options.cell_size * n / 2);
  const Eigen::Vector3f offset = options.offset.cast<float>();
  // the grid is made in XY and turned into its plane as GridDisplay::updatePlane does (L208-224)
  Eigen::Matrix3f to_plane = Eigen::Matrix3f::Identity();
  if (options.plane == GridOptions::Plane::kXZ) {
    to_plane = Eigen::AngleAxisf(-std::numbers::pi_v<float> / 2, Eigen::Vector3f::UnitX());
  } else if (options.plane == GridOptions::Plane::kYZ) {
    to_plane = Eigen::AngleAxisf(std::numbers::pi_v<float> / 2, Eigen::Vector3f::UnitY());
  }
  const auto add = [&](float x, float y) { grid.points.push_back(offset + to_plane * Eigen::Vector3f(x, y, 0)); };
  for (int i = 0; i <= n; ++i) {
    const float t = -extent + static_cast<float>(options.cell_size * i);
    add(t, -extent);
    add(t, extent);
    add(-extent, t);
    add(extent, t);
  }
  return grid;
}

}  // namespace urdfsnap::scene
