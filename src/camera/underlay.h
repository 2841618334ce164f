// A real camera image behind the rendered robot, as RViz's Camera display draws it by default
// ("Image Rendering: background and overlay"): the image replaces the background, and is drawn
// again over everything with "Overlay Alpha" (default 0.5), so the robot shows half-transparent
// over its own picture and misalignment is seen at a glance. RViz draws the overlay over all it
// shows (the Camera display's Visibility: robot, grid, markers, paths, clouds, scans alike), so
// every drawn pixel is blended, not the robot's alone.
#pragma once

#include <string>

#include <Eigen/Core>

#include "image/image.h"

namespace urdfsnap::camera {

// RViz's Overlay Alpha default (camera_display.cpp).
inline constexpr double kDefaultOverlayAlpha = 0.5;

// The pixels of a render (before the camera's distortion) where something was drawn, nonzero in
// the returned image: a robot link's (`drawn.labels`, kept as they are) or, elsewhere, a colour
// other than `background` (the scene's clear colour), which is where a display or the grid drew.
// A display drawn in exactly the background colour is taken for the background.
image::LabelImage DrawnPixels(const image::Frame& drawn, const Eigen::Vector3f& background);

// Draws `underlay` into `colour`: where `drawn` is nonzero, alpha·underlay + (1 − alpha)·colour;
// elsewhere the underlay itself (what RViz shows where only the background image is). Throws
// urdfsnap::Error naming `name` when the underlay's size differs from the image's.
void DrawUnderlay(const image::Image& underlay, const std::string& name, double alpha,
                  const image::LabelImage& drawn, image::Image& colour);

}  // namespace urdfsnap::camera
