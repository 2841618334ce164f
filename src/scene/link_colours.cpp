// RViz's per-link material bookkeeping ("latest used material becomes the default for this link").
#include "scene/link_colours.h"

#include <optional>

namespace urdfsnap::scene {

namespace {

// RViz clones "RVIZ/ShadedRed" for a link without a usable material (robot_link.cpp L486-490).
const LinkMaterial kRed{{1, 0, 0, 1}, ""};

// RobotLink::getMaterialForLink: the colour RViz builds for `material` in `link`.
LinkMaterial MaterialColour(const urdf::Link& link, urdf::MaterialSharedPtr material) {
  // "only the first visual's material actually comprises color values": look the name up there
  if (material && !material->name.empty()) {
    for (const auto& visual : link.visual_array) {
      if (visual->material_name == material->name) {
        material = visual->material;
        break;
      }
    }
  }
  if (!material && link.visual && link.visual->material) material = link.visual->material;
  if (!material) return kRed;
  if (!material->texture_filename.empty()) return {{1, 1, 1, 1}, material->texture_filename};
  const urdf::Color& c = material->color;
  return {{c.r, c.g, c.b, c.a}, ""};
}

}  // namespace

LinkColours ResolveLinkColours(const urdf::Link& link) {
  LinkColours colours;
  std::optional<LinkMaterial> current;   // RobotLink::default_material_
  for (const auto& visual : link.visual_array) {
    if (visual->geometry && (!current || visual->material)) {
      current = MaterialColour(link, visual->material);
    }
    colours.visuals.push_back(current.value_or(kRed));
  }
  colours.collision = current.value_or(kRed);
  return colours;
}

}  // namespace urdfsnap::scene
