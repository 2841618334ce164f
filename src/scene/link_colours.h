// The colours RViz gives a link's visuals and collision shapes: its material rules, including the
// surprising ones (src/rviz/robot/robot_link.cpp getMaterialForLink, createEntityForGeometryElement).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/robot.h"

namespace urdfsnap::scene {

// What RViz builds from a URDF material: a colour, or a texture on white (getMaterialForLink sets
// no colour on a textured material, so Ogre's default white diffuse stays and the texture shows
// lit but untinted).
struct LinkMaterial {
  Eigen::Vector4f rgba{1, 0, 0, 1};
  std::string texture;                    // the <texture filename> URI; "" for none
};

struct LinkColours {
  std::vector<LinkMaterial> visuals;      // per entry of link.visuals
  LinkMaterial collision;                 // for every collision shape of the link
};

// Applies RViz's rules, in its order (visuals, then collisions):
//  - a visual with a material uses the material of the first visual of the link that names the
//    same material (urdfdom already made robot-level materials win over inline colours of the
//    same name);
//  - a visual without a material keeps the link's current material: that of the last visual
//    before it that had one, or, before any, the first visual's material, else red;
//  - collision shapes take the link's current material after all visuals, else red.
LinkColours ResolveLinkColours(const model::Link& link);

}  // namespace urdfsnap::scene
