// RViz's orbit camera ("rviz/Orbit", the default view controller): where the eye is for a yaw,
// pitch, distance and focal point, and the OpenGL view and projection matrices it implies.
#pragma once

#include <Eigen/Geometry>

namespace urdfsnap::scene {

// The Orbit view's properties with RViz's defaults
// (src/rviz/default_plugin/view_controllers/orbit_view_controller.cpp L52-55, L81-88;
// src/rviz/view_controller.cpp L58-62 for the near clip).
struct OrbitView {
  double yaw = 0.785398;              // rad, about the fixed frame's +Z, 0 looks from +X
  double pitch = 0.785398;            // rad, above the XY plane; kept within ±(π/2 − 0.001)
  double distance = 10.0;             // m from the focal point
  Eigen::Vector3d focal{0, 0, 0};     // m, in the fixed frame
  double fov_y = 0.785398163397448;   // rad, vertical field of view (π/4)
  double near_clip = 0.01;            // m
  double far_clip = 100000.0;         // m, Ogre's default: RViz never sets it (OgreFrustum.cpp L40)
};

// The eye position in the fixed frame: focal + distance·(cos yaw cos pitch, sin yaw cos pitch,
// sin pitch), with pitch and distance limited as RViz limits them.
Eigen::Vector3d EyePosition(const OrbitView& view);

// World (fixed frame) to camera transform in OpenGL's convention (camera looks down −Z, +Y up),
// looking from EyePosition at the focal point with the fixed frame's +Z as the yaw axis (no roll).
Eigen::Matrix4d ViewMatrix(const OrbitView& view);

// Perspective projection for the given width/height aspect ratio.
Eigen::Matrix4d ProjectionMatrix(const OrbitView& view, double aspect);

}  // namespace urdfsnap::scene
