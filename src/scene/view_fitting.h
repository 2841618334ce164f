// --fit: an orbit view that frames the whole scene, or every scene of an animation, tightly and
// centred, for documentation images.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::scene {

// The empty border --fit leaves on each side, as a fraction of the image's width (x) and height
// (y).
struct FitMargin {
  double x = 0.05;
  double y = 0.05;
};

// Returns `view` seen from the same direction (yaw, pitch, field of view) with the eye placed so
// that the silhouette of every draw item of every scene `scene_of(k)`, k = 0 .. count-1, projected
// through that view, is centred in the image both ways and fills it up to `margin` in the
// direction where it is widest for the image's aspect. The focal point is put on the line of sight
// at the depth of the middle of the vertices, so orbiting from there turns about the robot.
// With keep_focal, the focal point stays and only the distance is chosen: the least at which every
// vertex is inside the frame shrunk by `margin` (centred on the focal point, not on the robot).
// Scenes are asked for once and not kept, so memory does not grow with `count`; a scene placed
// exactly as the one before it adds nothing and its vertices are not visited again. No vertices:
// `view` unchanged.
OrbitView FitView(int count, const std::function<Scene(int)>& scene_of, OrbitView view, double aspect,
                  bool keep_focal, FitMargin margin = {});

// FitView for one scene.
OrbitView FitView(const Scene& scene, OrbitView view, double aspect, bool keep_focal, FitMargin margin = {});

// The centre of the bounding box of every vertex of every scene (none: nullopt), the point a
// turntable turns about.
std::optional<Eigen::Vector3d> BoundsCentre(int count, const std::function<Scene(int)>& scene_of);

// The largest of the distances FitView(scene, view with each of `yaws`, aspect, true, margin) gives,
// exactly, with the scene's vertices placed once for all yaws (a turntable's frames). No vertices: 0.
double FitDistance(const Scene& scene, const OrbitView& view, const std::vector<double>& yaws, double aspect,
                   FitMargin margin = {});

}  // namespace urdfsnap::scene
