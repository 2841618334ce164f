// One visualization_msgs/Marker as scene items, every type drawn as RViz 1.14's marker classes
// draw it (src/rviz/default_plugin/markers/*.cpp): shapes lit like the robot, lines as billboard
// ribbons, points as camera-facing squares, text facing the camera, meshes from their files.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "display/display_messages.h"
#include "geometry/mesh_file.h"
#include "scene/scene.h"

namespace urdfsnap::display {

// What drawing a marker needs from outside: the file a MESH_RESOURCE names, loaded (or an
// urdfsnap::Error thrown saying why not, e.g. a package:// URI that does not resolve).
struct MarkerResources {
  std::function<std::shared_ptr<const geometry::MeshFile>(const std::string& uri)> load_mesh;
};

// The marker's pose as RViz uses it (marker_base.cpp transform): an all-zero quaternion is the
// identity, any other is normalised.
Eigen::Isometry3d MarkerPose(const Pose& pose);

// What RViz refuses to draw in `marker`, as its display's status says it, or "" when it can be
// drawn: a NaN or infinite number (marker_display.cpp validateFloats), an unknown type, an ARROW
// with other than 0 or 2 points, a LINE_LIST with an odd number of points, a TRIANGLE_LIST whose
// points are not whole triangles, a MESH_RESOURCE without a resource.
std::string MarkerProblem(const Marker& marker);

// The parts of a marker's geometry that stay while the marker does, made once when it is received
// (MakeMarkerMeshes) rather than every frame, so that its GPU copy is made once too: the lit mesh
// of a TRIANGLE_LIST without colours (LitTriangleMesh); null for other markers.
struct MarkerMeshes {
  std::shared_ptr<const geometry::TriangleMesh> lit_triangles;
};
MarkerMeshes MakeMarkerMeshes(const Marker& marker);

// triangle_list_marker.cpp without colours: every three points (scaled by scale) a triangle drawn
// from both sides, each side's normal from the points' winding, so a face seen from behind is lit
// from behind: black. Each triangle twice, once per winding, both with that normal.
std::shared_ptr<const geometry::TriangleMesh> LitTriangleMesh(const Marker& marker);

// Adds `marker`, which MarkerProblem accepts, to `scene`; X_FH: the marker's header frame in the
// fixed frame; `meshes`: MakeMarkerMeshes(marker) when the caller keeps it (the 4-argument form
// makes what it needs anew). Throws urdfsnap::Error when its mesh or font cannot be loaded.
void AddMarker(const Marker& marker, const MarkerMeshes& meshes, const Eigen::Isometry3d& X_FH,
               const MarkerResources& resources, scene::Scene& scene);
void AddMarker(const Marker& marker, const Eigen::Isometry3d& X_FH, const MarkerResources& resources,
               scene::Scene& scene);

}  // namespace urdfsnap::display
