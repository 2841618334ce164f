// RepeatedScenes: scenes compared field by field (shared meshes and textures by identity), the
// distinct ones kept while the section's pictures are classified; images kept until their last
// repeat.
#include "docs/repeated_scenes.h"

#include <algorithm>

namespace urdfsnap::docs {

namespace {

template <typename T, typename Same>
bool SameList(const std::vector<T>& a, const std::vector<T>& b, Same same) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), same);
}

bool SameItem(const scene::DrawItem& a, const scene::DrawItem& b) {
  return a.mesh == b.mesh && a.X_FG.matrix() == b.X_FG.matrix() && a.rgba == b.rgba && a.link == b.link &&
         a.texture == b.texture && a.texture_units == b.texture_units && a.emissive == b.emissive;
}

bool SameLines(const scene::LineSet& a, const scene::LineSet& b) {
  return a.points == b.points && a.rgba == b.rgba && a.colours == b.colours && a.width == b.width;
}

bool SameLabel(const scene::TextLabel& a, const scene::TextLabel& b) {
  // a label's texture and quads are made from its text alone: one texture, one text
  return a.texture == b.texture && a.quads.size() == b.quads.size() && a.anchor == b.anchor && a.rgba == b.rgba;
}

bool SamePoints(const scene::PointSet& a, const scene::PointSet& b) {
  return a.style == b.style && a.positions == b.positions && a.colours == b.colours && a.size == b.size &&
         a.box_axes == b.box_axes;
}

bool SameTriangles(const scene::FlatTriangles& a, const scene::FlatTriangles& b) {
  return a.positions == b.positions && a.colours == b.colours;
}

}  // namespace

bool SameScene(const scene::Scene& a, const scene::Scene& b) {
  return a.background == b.background && SameList(a.items, b.items, SameItem) &&
         SameList(a.lines, b.lines, SameLines) && SameList(a.labels, b.labels, SameLabel) &&
         SameList(a.points, b.points, SamePoints) && SameList(a.triangles, b.triangles, SameTriangles);
}

RepeatedScenes::RepeatedScenes(int count, const std::function<scene::Scene(int)>& posed)
    : first_(count), last_(count) {
  std::vector<scene::Scene> distinct;
  std::vector<int> distinct_picture;
  for (int k = 0; k < count; ++k) {
    scene::Scene scene = posed(k);
    const auto same = std::find_if(distinct.begin(), distinct.end(),
                                   [&](const scene::Scene& earlier) { return SameScene(earlier, scene); });
    if (same == distinct.end()) {
      first_[k] = k;
      distinct.push_back(std::move(scene));
      distinct_picture.push_back(k);
    } else {
      first_[k] = distinct_picture[same - distinct.begin()];
    }
    last_[first_[k]] = k;
  }
}

image::Image RepeatedScenes::Picture(int k, const std::function<image::Image()>& draw) {
  const int first = first_[k];
  const auto kept = kept_.find(first);
  // the first picture, or a repeat of one this piece of the page did not draw
  image::Image image = kept != kept_.end() ? kept->second : draw();
  if (last_[first] > k) {
    kept_[first] = image;
  } else {
    kept_.erase(first);
  }
  return image;
}

}  // namespace urdfsnap::docs
