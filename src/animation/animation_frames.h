// What each frame of an animation shows: the robot's joint positions (a trajectory sampled at the
// frame's time through motion::FramePoses) and the camera, one for the whole animation so that the
// view never jumps: --fit fitted once over every frame, a turntable's yaw turned once around.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/warnings.h"
#include "animation/followed_frame.h"
#include "animation/frame_displays.h"
#include "animation/frame_underlay.h"
#include "animation/tf_display.h"
#include "motion/frame_plan.h"
#include "motion/frame_poses.h"
#include "motion/root_poses.h"
#include "render/render_settings.h"
#include "render/robot_renderer.h"
#include "scene/orbit_view.h"

namespace urdfsnap::animation {

// The camera an animation asks for, before fitting.
struct CameraRequest {
  scene::OrbitView view;  // the view of frame 0 (before --fit)
  render::ImageSize size;
  render::Fit fit = render::Fit::kNone;
  render::FitMargin fit_margin;
  bool turntable = false;  // the yaw turns once around over the animation
  std::optional<render::CameraSettings> camera;   // when set, every frame is seen through it instead
  // when set, camera->frame is a TF frame of the bag (not a link): its pose in the robot's root
  // link at each frame's time (kept by reference)
  const motion::RootPoses* camera_tf = nullptr;
};

// What a recording adds to each frame, each kept by reference when given: where TF places the
// robot in a fixed frame outside it, the TF display of its frames, the frame the view follows, the
// message displays (fed as frames advance: their scenes are asked for in time order), the camera
// image behind a calibrated camera (fed likewise: cameras asked for in time order).
struct SceneAdditions {
  const motion::RootPoses* root = nullptr;
  const TfDisplay* tf = nullptr;
  const FollowedFrame* follow = nullptr;
  FrameDisplays* displays = nullptr;
  FrameUnderlay* underlay = nullptr;
};

class AnimationFrames {
 public:
  // Fits the camera for `robot` over every frame of `plan` (kept by reference, as `poses` is). With
  // --fit the focal point is the centre of the bounds of all frames (or the given one) and the
  // distance the least that frames every frame; a fitted turntable takes the least distance that
  // frames each frame from its own yaw. Poses are made as they are needed and not kept, so fitting
  // takes time in proportion to the frame count and no memory for it (two poses per frame, four
  // for a fitted turntable). Warnings of the poses (see FramePoses::At) go to `warnings`.
  // `additions` place the robot, draw the TF display and move the focal point per frame; with a
  // fitted camera the followed frame is not followed (one warning): the fit frames the whole motion
  // from one place.
  AnimationFrames(const render::RobotRenderer& robot, const motion::FramePlan& plan,
                  const motion::FramePoses& poses, const CameraRequest& camera, Warnings& warnings,
                  SceneAdditions additions = {});

  std::int64_t count() const { return plan_.frame_count; }
  const motion::FramePlan& plan() const { return plan_; }
  render::ImageSize size() const { return size_; }

  // The joint positions of frame `k` (one per robot joint, radians or metres, as
  // model::ResolveJointPositions gives them).
  std::vector<double> Positions(std::int64_t k, Warnings& warnings) const;
  // Where frame `k` places the robot's fixed link in the scene (identity without `root`).
  Eigen::Isometry3d Place(std::int64_t k, Warnings& warnings) const;
  // The scene of frame `k`: `robot` (the renderer the frames were fitted for) posed and placed,
  // with the TF display and the message displays when there are. With message displays, frames are
  // asked for in time order.
  scene::Scene Scene(const render::RobotRenderer& robot, std::int64_t k, Warnings& warnings) const;
  // The camera of frame `k` (its focal point relative to the followed frame's origin then).
  scene::OrbitView View(std::int64_t k) const;
  // Frame 0's camera as fitted (the request's view when nothing was fitted): given back as the
  // request's view without --fit, it makes the same frames.
  const scene::OrbitView& fitted_view() const { return view_; }
  // The frame the view follows, if any (none with a fitted camera).
  const FollowedFrame* followed() const { return additions_.follow; }
  // The calibrated camera frame `k` is seen through, if one was asked for (View is then unused):
  // the same for every frame unless its frame is a TF frame of the bag, which moves it per frame,
  // or a bag's camera image is behind it (the image of the frame's moment: frames asked for in
  // time order; throws urdfsnap::Error as FrameUnderlay::Attach does).
  std::optional<render::CameraSettings> Camera(std::int64_t k, Warnings& warnings) const;

 private:
  const motion::FramePlan& plan_;
  const motion::FramePoses& poses_;
  SceneAdditions additions_;
  render::ImageSize size_;
  bool turntable_;
  scene::OrbitView view_;  // frame 0's, fitted
  std::optional<render::CameraSettings> camera_;
  const motion::RootPoses* camera_tf_;
};

}  // namespace urdfsnap::animation
