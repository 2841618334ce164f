// The frame names of a docs page's TF picture made readable on robots with many frames close
// together (a PR2's dozens, a Panda's hand): each name drawn at one size in pixels wherever its
// frame is, moved to a row above or below its frame when another name is in the way, and left out when no place
// is free, the page's legend then naming it with the name drawn nearest. GL-free: it changes the
// scene's labels, which the GL backend draws.
#pragma once

#include <string>
#include <vector>

#include "render/render_settings.h"
#include "scene/orbit_view.h"
#include "scene/scene.h"

namespace urdfsnap::docs {

// A frame whose name the picture leaves out, and the frame named in the picture nearest to it.
struct LeftOutName {
  std::string frame;
  std::string near;
};

// Lays out `scene.labels`, the names of `frames` (one label per frame, in order, as the TF display
// adds them) seen through `view` in a picture of `size`: each scaled to `pixels` high, centred on
// its frame and put in the row below it, above it, or one row further below or above, the first
// of these that overlaps no name placed before it (frames in order), and brought nearer the eye
// (to the same pixels) so that the geometry around its frame does not hide it; a name with no
// such place is removed. Returns those, in order.
std::vector<LeftOutName> LayOutTfNames(scene::Scene& scene, const std::vector<std::string>& frames,
                                       const scene::OrbitView& view, render::ImageSize size, double pixels = 15);

// The page's sentence about the names left out ("" when there are none).
std::string LeftOutNote(const std::vector<LeftOutName>& left_out);

}  // namespace urdfsnap::docs
