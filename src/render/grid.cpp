// Grid line generation, as RViz's Grid::create does for the "Lines" style with no normal cells.
#include "render/grid.h"

namespace urdfsnap::render {

LineSet MakeGrid(const GridOptions& options) {
  LineSet grid;
  grid.rgba << options.colour, options.alpha;
  const int n = options.plane_cell_count;
  const float extent = static_cast<float>(options.cell_size * n / 2);
  const Eigen::Vector3f offset = options.offset.cast<float>();
  for (int i = 0; i <= n; ++i) {
    const float t = -extent + static_cast<float>(options.cell_size * i);
    grid.points.push_back(offset + Eigen::Vector3f(t, -extent, 0));
    grid.points.push_back(offset + Eigen::Vector3f(t, extent, 0));
    grid.points.push_back(offset + Eigen::Vector3f(-extent, t, 0));
    grid.points.push_back(offset + Eigen::Vector3f(extent, t, 0));
  }
  return grid;
}

}  // namespace urdfsnap::render
