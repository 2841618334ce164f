// --fit: an orbit view that frames the whole scene, for documentation images.
#pragma once

#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::scene {

// Returns `view` with the focal point at the centre of the scene's draw items' bounding box (when
// keep_focal is false) and the smallest distance at which every vertex of every item projects
// inside the image shrunk by `margin` (a fraction of each side) at that yaw, pitch and field of
// view. An empty scene returns `view` unchanged.
OrbitView FitView(const Scene& scene, OrbitView view, double aspect, bool keep_focal,
                  double margin = 0.05);

}  // namespace urdfsnap::scene
