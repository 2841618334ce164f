// RViz's TF display as draw items: per frame its axes, its name, and an arrow from each frame to its
// parent (src/rviz/default_plugin/tf_display.cpp, ogre_helpers/axes.cpp, ogre_helpers/arrow.cpp,
// ogre_helpers/movable_text.cpp).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "model/robot.h"
#include "scene/scene.h"

namespace urdfsnap::scene {

// The TF display's properties with RViz's defaults (tf_display.cpp L164-191); off unless asked.
struct TfOptions {
  bool enabled = false;
  bool show_names = true;
  bool show_axes = true;
  bool show_arrows = true;
  double marker_scale = 1.0;
  // RViz draws frame names white whatever the background (tf_display.cpp); a background given on
  // the command line picks NameColourOn(background) instead, so that names stay readable
  Eigen::Vector4f name_colour{1, 1, 1, 1};

  bool operator==(const TfOptions&) const = default;
};

// The colour frame names are readable in on `background`: RViz's white, or black on a background
// brighter than mid-grey (Rec. 709 luma above 0.6), as documentation pictures on white have.
Eigen::Vector4f NameColourOn(const Eigen::Vector3f& background);

// The names `frames` as text labels (one per name, anchored at the origin), laid out once with
// Liberation Sans at the marker scale. Throws urdfsnap::Error when the font is missing.
std::vector<TextLabel> MakeTfNameLabels(const std::vector<std::string>& frames, const TfOptions& options);
// The link names of `robot` as MakeTfNameLabels lays them out.
std::vector<TextLabel> MakeTfNameLabels(const model::Robot& robot, const TfOptions& options);

// Adds the axes of every frame and its arrow to its parent as `options` ask, and `names` (from
// MakeTfNameLabels, one per frame, or empty) moved to the frames. X_FT: frame poses in the fixed
// frame; parents: per frame the index of its parent in X_FT, or -1 for none (no arrow).
void AddTfFrames(const std::vector<Eigen::Isometry3d>& X_FT, const std::vector<int>& parents,
                 const TfOptions& options, const std::vector<TextLabel>& names, Scene& scene);

}  // namespace urdfsnap::scene
