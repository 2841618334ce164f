// LayOutTfNames: each label's anchor projected through the orbit view, its glyph quads (metres in
// the image plane at the anchor) scaled and moved in whole pixels, and placed greedily.
#include "docs/tf_name_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "common/error.h"

namespace urdfsnap::docs {

namespace {

// A rectangle in pixels, y down.
struct Box {
  double left, top, right, bottom;
  bool Overlaps(const Box& other) const {
    return left < other.right && other.left < right && top < other.bottom && other.top < bottom;
  }
};

constexpr double kGap = 2;   // pixels between a frame's origin and its name, and between names
constexpr int kRows[] = {0, -1, 1, -2};   // the rows a name may take: 0 below its frame, -1 above
constexpr double kPull = 0.75;            // a name's distance from the eye, a share of its frame's

}  // namespace

std::vector<LeftOutName> LayOutTfNames(scene::Scene& scene, const std::vector<std::string>& frames,
                                       const scene::OrbitView& view, render::ImageSize size, double pixels) {
  if (scene.labels.size() != frames.size()) {
    throw Error("TF names: " + std::to_string(scene.labels.size()) + " labels for " + std::to_string(frames.size()) +
                " frames");
  }
  const Eigen::Matrix4d view_matrix = scene::ViewMatrix(view);
  const Eigen::Matrix4d clip_matrix = scene::ProjectionMatrix(view, static_cast<double>(size.width) / size.height);
  const double focal_pixels = size.height / 2.0 / std::tan(view.fov_y / 2);
  const Eigen::Vector3d eye_position = scene::EyePosition(view);
  std::vector<Box> placed;
  std::vector<Eigen::Vector2d> placed_at;   // the frame's pixel of each placed name
  std::vector<size_t> placed_frame;
  std::vector<scene::TextLabel> kept;
  std::vector<LeftOutName> left_out;
  std::vector<std::pair<size_t, Eigen::Vector2d>> unplaced;
  for (size_t i = 0; i < frames.size(); ++i) {
    scene::TextLabel label = scene.labels[i];
    const Eigen::Vector4d clip = clip_matrix * view_matrix * label.anchor.homogeneous();
    if (label.quads.empty() || clip.w() <= view.near_clip) continue;   // behind the camera
    // pulled along its ray towards the eye, where it projects to the same pixel: in front of the
    // axes and geometry around its frame, which would hide parts of it
    label.anchor = eye_position + (label.anchor - eye_position) * kPull;
    const Eigen::Vector4d eye = view_matrix * label.anchor.homogeneous();
    const Eigen::Vector2d at((clip.x() / clip.w() + 1) / 2 * size.width, (1 - clip.y() / clip.w()) / 2 * size.height);
    // the name's extent in metres, then in pixels once scaled to `pixels` high
    Eigen::Vector2f low = label.quads.front().min, high = label.quads.front().max;
    for (const scene::GlyphQuad& quad : label.quads) {
      low = low.cwiseMin(quad.min);
      high = high.cwiseMax(quad.max);
    }
    const double metres_per_pixel = -eye.z() / focal_pixels;
    const double scale = pixels * metres_per_pixel / std::max(1e-9f, high.y() - low.y());
    const double width = (high.x() - low.x()) * scale / metres_per_pixel;
    // where the name's top-left corner goes, relative to the frame's pixel: centred on it, in the
    // row below it (RViz's place), above it, or one row further below or above
    std::vector<Eigen::Vector2d> corners;
    for (const int row : kRows) corners.emplace_back(-width / 2, kGap + row * (pixels + 2 * kGap));
    bool done = false;
    for (const Eigen::Vector2d& corner : corners) {
      const Eigen::Vector2d top_left = (at + corner).array().round();
      const Box box{top_left.x() - kGap, top_left.y() - kGap, top_left.x() + width + kGap, top_left.y() + pixels + kGap};
      if (std::any_of(placed.begin(), placed.end(), [&](const Box& other) { return box.Overlaps(other); })) continue;
      // the quads scaled about the name's top-left corner and moved there (metres, y up)
      const Eigen::Vector2f shift((top_left.x() - at.x()) * metres_per_pixel,
                                  -(top_left.y() - at.y()) * metres_per_pixel);
      const Eigen::Vector2f corner_m(low.x(), high.y());
      for (scene::GlyphQuad& quad : label.quads) {
        quad.min = (quad.min - corner_m) * static_cast<float>(scale) + shift;
        quad.max = (quad.max - corner_m) * static_cast<float>(scale) + shift;
      }
      placed.push_back(box);
      placed_at.push_back(at);
      placed_frame.push_back(i);
      kept.push_back(std::move(label));
      done = true;
      break;
    }
    if (!done) unplaced.emplace_back(i, at);
  }
  for (const auto& [frame, at] : unplaced) {
    size_t nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < placed_at.size(); ++k) {
      if (const double distance = (placed_at[k] - at).squaredNorm(); distance < best) {
        best = distance;
        nearest = k;
      }
    }
    left_out.push_back({frames[frame], placed_at.empty() ? "" : frames[placed_frame[nearest]]});
  }
  scene.labels = std::move(kept);
  return left_out;
}

std::string LeftOutNote(const std::vector<LeftOutName>& left_out) {
  if (left_out.empty()) return "";
  // grouped by the name drawn nearest, in the order those first appear
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::string>> near;
  for (const LeftOutName& name : left_out) {
    if (!near.count(name.near)) order.push_back(name.near);
    near[name.near].push_back(name.frame);
  }
  std::string note = "The TF picture leaves out " + std::to_string(left_out.size()) + " frame name" +
                     (left_out.size() == 1 ? "" : "s") + " that would overlap others; each is listed by the name drawn nearest it:";
  for (size_t g = 0; g < order.size(); ++g) {
    std::string names;
    for (const std::string& frame : near[order[g]]) names += (names.empty() ? "" : ", ") + frame;
    note += (g ? "; " : " ") + (order[g].empty() ? names : names + " near " + order[g]);
  }
  return note + ".";
}

}  // namespace urdfsnap::docs
