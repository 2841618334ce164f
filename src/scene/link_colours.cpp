// RViz's per-link material bookkeeping ("latest used material becomes the default for this link").
#include "scene/link_colours.h"

#include <optional>

namespace urdfsnap::scene {

namespace {

// RViz clones "RVIZ/ShadedRed" for a link without a usable material (robot_link.cpp L486-490).
const LinkMaterial kRed{{1, 0, 0, 1}, ""};

// RobotLink::getMaterialForLink: the colour RViz builds for `material` in `link`.
LinkMaterial MaterialColour(const model::Link& link, const std::optional<model::Material>& given) {
  const model::Material* material = given ? &*given : nullptr;
  // "only the first visual's material actually comprises color values": look the name up there
  if (material && !material->name.empty()) {
    for (const auto& visual : link.visuals) {
      if (visual.material_name == material->name) {
        material = visual.material ? &*visual.material : nullptr;
        break;
      }
    }
  }
  // urdfdom's link.visual is the first visual
  if (!material && !link.visuals.empty() && link.visuals[0].material) material = &*link.visuals[0].material;
  if (!material) return kRed;
  if (!material->texture.empty()) return {{1, 1, 1, 1}, material->texture};
  return {material->rgba, ""};
}

}  // namespace

LinkColours ResolveLinkColours(const model::Link& link) {
  LinkColours colours;
  std::optional<LinkMaterial> current;   // RobotLink::default_material_
  for (const auto& visual : link.visuals) {
    if (!current || visual.material) current = MaterialColour(link, visual.material);
    colours.visuals.push_back(current.value_or(kRed));
  }
  colours.collision = current.value_or(kRed);
  return colours;
}

}  // namespace urdfsnap::scene
