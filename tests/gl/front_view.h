// The view the GL tests draw from: looking down -X at the origin from 2 m away, so the image plane
// is the world's YZ plane (+Y to the right, +Z up) and the viewing axis is -X.
#pragma once

#include "scene/orbit_view.h"

namespace urdfsnap::gl {

inline scene::OrbitView FrontView() {
  scene::OrbitView view;
  view.yaw = 0;
  view.pitch = 0;
  view.distance = 2;
  return view;
}

}  // namespace urdfsnap::gl
