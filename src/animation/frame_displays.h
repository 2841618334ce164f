// RViz's message displays (display/display_set.h) in the frames of an animation, and so in
// `render --bag`'s still, which is frame 0 of a one-frame animation: at each frame the displays are
// fed the bag's messages logged up to the frame's stamp (display::BagDisplayFeed: one pass, frames
// in time order), then draw what they keep at that stamp into the frame's scene. A message's frame
// is found through the bag's TF at its stamp, as RViz's FrameManager finds it, else among the
// robot's links posed as drawn (message files, bags without TF).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "display/bag_display_feed.h"
#include "display/display_set.h"
#include "render/robot_renderer.h"
#include "scene/scene.h"
#include "tf/tf_buffer.h"

namespace urdfsnap::animation {

class FrameDisplays {
 public:
  // `displays` drawn in the scene's frame, `fixed_frame` in the bag's TF `transforms` (the frame the
  // robot is placed in, else its fixed link); fed from the bag at `bag` ("" for none: their
  // messages are given already); trajectory time 0 is the stamp `stamp_at_zero` (seconds since
  // 1970).
  FrameDisplays(display::DisplaySet displays, const std::string& bag,
                std::shared_ptr<const tf::TfBuffer> transforms, std::string fixed_frame, double stamp_at_zero);
  FrameDisplays(const FrameDisplays&) = delete;
  FrameDisplays& operator=(const FrameDisplays&) = delete;

  // The stamp of trajectory time `t`, nanoseconds since 1970.
  std::int64_t Stamp(double t) const;

  // Feeds the displays up to the stamp of trajectory time `t` (which never goes back from one call
  // to the next) and adds what they show then to `scene`, the scene `robot` made for `positions`
  // with its fixed link placed at X_SF (render::RobotRenderer::Pose). Display problems are
  // warnings; throws urdfsnap::Error as display::BagDisplayFeed::AdvanceTo does.
  void AddTo(const render::RobotRenderer& robot, const std::vector<double>& positions, const Eigen::Isometry3d& X_SF,
             double t, scene::Scene& scene, Warnings& warnings);

  // Whether AddTo may still be asked for the stamp `stamp_ns`: no earlier AddTo went past it.
  bool CanShow(std::int64_t stamp_ns) const { return stamp_ns >= shown_ns_; }

 private:
  display::DisplaySet displays_;
  std::optional<display::BagDisplayFeed> feed_;   // feeds displays_
  std::shared_ptr<const tf::TfBuffer> transforms_;
  std::string fixed_frame_;
  double stamp_at_zero_;
  std::int64_t shown_ns_ = INT64_MIN;   // the stamp of the last AddTo
};

}  // namespace urdfsnap::animation
