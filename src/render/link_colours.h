// The colours RViz gives a link's visuals and collision shapes: its material rules, including the
// surprising ones (src/rviz/robot/robot_link.cpp getMaterialForLink, createEntityForGeometryElement).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <urdf_model/link.h>

namespace urdfsnap::render {

struct LinkColours {
  std::vector<Eigen::Vector4f> visuals;   // rgba per entry of link.visual_array
  Eigen::Vector4f collision{1, 0, 0, 1};  // rgba for every collision shape of the link
};

// Applies RViz's rules, in its order (visuals, then collisions):
//  - a visual with a material uses the first visual of the link that names the same material
//    (urdfdom already made robot-level materials win over inline colours of the same name);
//  - a visual without a material keeps the link's current material: that of the last visual
//    before it that had one, or, before any, the first visual's material, else red;
//  - collision shapes take the link's current material after all visuals, else red.
LinkColours ResolveLinkColours(const urdf::Link& link);

}  // namespace urdfsnap::render
