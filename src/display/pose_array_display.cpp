// The PoseArray display's three shapes.
#include "display/pose_array_display.h"

#include "display/arrow_shapes.h"
#include "display/marker_shapes.h"

namespace urdfsnap::display {

PoseArrayDisplay::PoseArrayDisplay(std::string topic, PoseArraySettings settings)
    : PoseListDisplay(std::move(topic), "geometry_msgs/PoseArray", 1), settings_(std::move(settings)) {}

void PoseArrayDisplay::DrawPoses(const PoseList& poses, const Eigen::Isometry3d& X_FH,
                                 scene::Scene& scene) const {
  const PoseArraySettings& s = settings_;
  Eigen::Vector4f rgba;
  rgba << s.colour, s.alpha;
  scene::LineSet flat;
  flat.rgba = rgba;
  for (const Pose& pose : poses.poses) {
    const Eigen::Isometry3d X_FP = X_FH * MarkerPose(pose);
    switch (s.shape) {
      case PoseArraySettings::Shape::kArrowFlat: {
        // pose_array_display.cpp updateArrows2d: the shaft along x, two barbs back from the tip
        const double L = s.arrow_length;
        const Eigen::Vector3f tip = (X_FP * Eigen::Vector3d(L, 0, 0)).cast<float>();
        for (const Eigen::Vector3d& from : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.75 * L, 0.2 * L, 0),
                                            Eigen::Vector3d(0.75 * L, -0.2 * L, 0)}) {
          flat.points.push_back((X_FP * from).cast<float>());
          flat.points.push_back(tip);
        }
        break;
      }
      case PoseArraySettings::Shape::kArrow3d:
        // updateArrows3d: Arrow::set(shaft length, 2 * shaft radius, head length, 2 * head radius)
        AddArrow(X_FP,
                 {s.shaft_length, {2 * s.shaft_radius, 2 * s.shaft_radius}, s.head_length,
                  {2 * s.head_radius, 2 * s.head_radius}},
                 rgba, scene);
        break;
      case PoseArraySettings::Shape::kAxes:
        AddAxes(X_FP, s.axes_length, s.axes_radius, 1, scene);
        break;
    }
  }
  if (!flat.points.empty()) scene.lines.push_back(std::move(flat));
}

}  // namespace urdfsnap::display
