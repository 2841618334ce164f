// A real camera image behind the rendered robot, as RViz's Camera display draws it by default
// ("Image Rendering: background and overlay"): the image replaces the background, and is drawn
// again over everything with "Overlay Alpha" (default 0.5), so the robot shows half-transparent
// over its own picture and misalignment is seen at a glance.
#pragma once

#include <string>

#include "image/image.h"

namespace urdfsnap::camera {

// RViz's Overlay Alpha default (camera_display.cpp).
inline constexpr double kDefaultOverlayAlpha = 0.5;

// Draws `underlay` into `colour`: where `robot` has a label, alpha·underlay + (1 − alpha)·colour;
// elsewhere the underlay itself (what RViz shows where only the background image is; other
// displays such as the grid are not composited). Throws urdfsnap::Error naming `name` when the
// underlay's size differs from the image's.
void DrawUnderlay(const image::Image& underlay, const std::string& name, double alpha,
                  const image::LabelImage& robot, image::Image& colour);

}  // namespace urdfsnap::camera
