// RViz's Grid display as line segments (src/rviz/ogre_helpers/grid.cpp, grid_display.cpp).
#pragma once

#include <Eigen/Core>

#include "scene/scene.h"

namespace urdfsnap::scene {

// The Grid display's properties with RViz's defaults (grid_display.cpp L54-99).
struct GridOptions {
  bool enabled = true;
  int plane_cell_count = 10;                                 // cells per side
  double cell_size = 1.0;                                    // m
  Eigen::Vector3f colour{160 / 255.f, 160 / 255.f, 164 / 255.f};   // Qt::gray
  float alpha = 0.5f;
  Eigen::Vector3d offset{0, 0, 0};                           // m, in the fixed frame
  enum class Plane { kXY, kXZ, kYZ } plane = Plane::kXY;     // grid_display.cpp L90-94

  bool operator==(const GridOptions&) const = default;
};

// plane_cell_count + 1 lines per direction in the chosen plane of the fixed frame, centred on the
// offset.
LineSet MakeGrid(const GridOptions& options);

}  // namespace urdfsnap::scene
