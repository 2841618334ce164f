// RViz's two composite shapes, ogre_helpers/arrow.cpp (a cylinder shaft and a cone head) and
// ogre_helpers/axes.cpp (three cylinders, red x, green y, blue z), as lit draw items. Shared by the
// ARROW marker, the PoseArray display's Arrow (3D) and Axes shapes, and the Axes display.
#pragma once

#include <Eigen/Geometry>

#include "scene/scene.h"

namespace urdfsnap::display {

// An arrow's proportions: lengths along the arrow and diameters across its local y and z.
struct ArrowSize {
  double shaft_length = 0.77;
  Eigen::Vector2d shaft_diameter{1.0, 1.0};
  double head_length = 0.23;
  Eigen::Vector2d head_diameter{2.0, 2.0};
};

// Adds an arrow that starts at X_FA's origin and points along its +x: the shaft from 0 to
// shaft_length, the head's base at the shaft's end (arrow.cpp's Arrow::set).
void AddArrow(const Eigen::Isometry3d& X_FA, const ArrowSize& size, const Eigen::Vector4f& rgba,
              scene::Scene& scene);

// Adds axes at X_FA: per axis a cylinder from the origin to `length` along it, `diameter` across
// (axes.cpp scales its unit-diameter cylinder by its `radius` argument, so that argument is the
// diameter), coloured red, green, blue with `alpha`.
void AddAxes(const Eigen::Isometry3d& X_FA, double length, double diameter, float alpha,
             scene::Scene& scene);

}  // namespace urdfsnap::display
