// The view the GL tests draw from: looking down -X at the origin from 2 m away, so the image plane
// is the world's YZ plane (+Y to the right, +Z up) and the viewing axis is -X; and a rectangle
// covering given pixels of it.
#pragma once

#include <cmath>
#include <memory>
#include <numbers>

#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::gl {

inline scene::OrbitView FrontView() {
  scene::OrbitView view;
  view.yaw = 0;
  view.pitch = 0;
  view.distance = 2;
  return view;
}

// A white rectangle facing the camera that covers, in image pixels (x right, y down from the top
// left corner), [x0, x1) x [y0, y1) of the FrontView() at 64x48.
inline scene::DrawItem ImageRectangle(double x0, double x1, double y0, double y1) {
  // FrontView: the image plane is x = 0 at 2 m, 48 rows span 2 · 2 · tan(22.5°)
  const double metres_per_pixel = 4 * std::tan(std::numbers::pi / 8) / 48;
  const auto corner = [&](double x, double y) {
    return Eigen::Vector3f(0, static_cast<float>((x - 32) * metres_per_pixel),
                           static_cast<float>((24 - y) * metres_per_pixel));
  };
  geometry::TriangleMesh mesh;
  mesh.positions = {corner(x0, y1), corner(x1, y1), corner(x1, y0), corner(x0, y0)};
  mesh.normals.assign(4, Eigen::Vector3f::UnitX());
  mesh.indices = {0, 1, 2, 0, 2, 3};
  scene::DrawItem item;
  item.mesh = std::make_shared<const geometry::TriangleMesh>(mesh);
  item.X_FG = Eigen::Affine3d::Identity();
  item.rgba = {1, 1, 1, 1};
  return item;
}

}  // namespace urdfsnap::gl
