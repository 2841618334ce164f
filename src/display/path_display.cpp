// The Path display's line.
#include "display/path_display.h"

namespace urdfsnap::display {

PathDisplay::PathDisplay(std::string topic, PathSettings settings)
    : PoseListDisplay(std::move(topic), "nav_msgs/Path", static_cast<size_t>(std::max(1, settings.buffer_length))),
      settings_(std::move(settings)) {}

void PathDisplay::DrawPoses(const PoseList& poses, const Eigen::Isometry3d& X_FH, scene::Scene& scene) const {
  if (poses.poses.size() < 2) return;
  scene::LineSet lines;
  lines.rgba << settings_.colour, settings_.alpha;
  if (settings_.line_style == PathSettings::LineStyle::kBillboards) {
    lines.width = static_cast<float>(settings_.line_width);
  }
  // path_display.cpp: the offset moves the path's node in the fixed frame
  const Eigen::Isometry3d X = Eigen::Translation3d(settings_.offset) * X_FH;
  for (size_t i = 1; i < poses.poses.size(); ++i) {
    lines.points.push_back((X * poses.poses[i - 1].position).cast<float>());
    lines.points.push_back((X * poses.poses[i].position).cast<float>());
  }
  scene.lines.push_back(std::move(lines));
}

}  // namespace urdfsnap::display
