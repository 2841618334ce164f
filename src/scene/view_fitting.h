// --fit: an orbit view that frames the whole scene, or every scene of an animation, for
// documentation images.
#pragma once

#include <functional>
#include <vector>

#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::scene {

// Returns `view` with the focal point at the centre of the bounding box of every draw item of
// every scene `scene_of(k)`, k = 0 .. count-1 (when keep_focal is false), and the smallest
// distance at which all their vertices project inside the image shrunk by `margin` (a fraction of
// each side) at that yaw, pitch and field of view. Scenes are asked for twice (bounds, then
// distance; once with keep_focal) and not kept, so memory does not grow with `count`; a scene
// placed exactly as the one before it adds nothing and its vertices are not visited again. No
// vertices: `view` unchanged.
OrbitView FitView(int count, const std::function<Scene(int)>& scene_of, OrbitView view, double aspect,
                  bool keep_focal, double margin = 0.05);

// FitView for one scene.
OrbitView FitView(const Scene& scene, OrbitView view, double aspect, bool keep_focal,
                  double margin = 0.05);

// The largest of the distances FitView(scene, view with each of `yaws`, aspect, true, margin) gives,
// with the scene's vertices placed once for all yaws (a turntable's frames). No vertices: 0.
double FitDistance(const Scene& scene, const OrbitView& view, const std::vector<double>& yaws, double aspect,
                   double margin = 0.05);

}  // namespace urdfsnap::scene
