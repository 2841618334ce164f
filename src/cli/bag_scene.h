// A robot drawn as RViz draws a recording: the fixed frame (--fixed-frame, else the .rviz file's
// Fixed Frame) resolved through the bag's TF when it is not a link of the robot (odom, map: the
// robot is then placed where TF puts its root at each moment), the TF display showing the bag's
// frames, robot and others, and the view's Target Frame (--follow) followed through the motion.
// A camera (--camera-frame) may hang off a frame of the bag's TF. Shared by `animate` (with or
// without a bag) and `render --bag`.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "animation/animation_frames.h"
#include "animation/followed_frame.h"
#include "animation/frame_displays.h"
#include "animation/frame_underlay.h"
#include "animation/tf_display.h"
#include "cli/bag_cache.h"
#include "cli/display_options.h"
#include "common/warnings.h"
#include "motion/root_poses.h"
#include "motion/trajectory.h"
#include "request/render_session.h"
#include "request/resolved_request.h"
#include "tf/tf_buffer.h"

namespace urdfsnap::cli {

struct BagScene {
  request::Prepared robot;    // prepared with the fixed frame when it is a link, else from the root
  std::shared_ptr<const tf::TfBuffer> transforms;   // the bag's /tf and /tf_static
  std::optional<motion::RootPoses> root;   // set for a fixed frame outside the robot
  std::optional<animation::TfDisplay> tf;  // set when the TF display is on
  std::optional<animation::FollowedFrame> follow;   // set for a target frame
  // set for a camera whose --camera-frame is a frame of the bag's TF, not a link: where TF puts
  // the robot's root in it at each moment (animation::CameraRequest::camera_tf)
  std::optional<motion::RootPoses> camera_tf;
  // set for message displays (AddSceneDisplays); shared with a BagCache that keeps them
  std::shared_ptr<animation::FrameDisplays> displays;
  std::optional<animation::FrameUnderlay> underlay;   // set for a bag's camera image (AddBagUnderlay)

  // What the scene adds to each frame, for animation::AnimationFrames (which feeds the displays).
  animation::SceneAdditions Additions();
};

// Prepares `resolved` (its fit left to the caller) for the recording `bag` ("" for none: no TF,
// the robot's links alone in the TF display), whose trajectory time 0 is the stamp `stamp_at_zero`
// (seconds since 1970), into `out`. With `model_from_bag` (the description the bag recorded), mesh
// file names relative to the description are found from the folder that holds the bag (a file's
// folder, a rosbag2 folder's parent), as they would be from a URDF file saved beside it. A fixed frame that is neither a link nor connected to the root
// by the bag's TF is an error when --fixed-frame gave it, and when an .rviz file gave it a warning,
// the root link then fixed as `render` does without a bag. Throws urdfsnap::Error as
// RenderSession::Prepare, tf::ReadBagTransforms and animation::FollowedFrame do. A `cache` gives
// the bag's TF read by an earlier still, or keeps it once read.
void PrepareBagScene(request::RenderSession& session, request::ResolvedRequest resolved, const std::string& bag,
                     double stamp_at_zero, bool model_from_bag, Warnings& warnings, BagScene& out,
                     BagCache* cache = nullptr);


// Adds the message displays of the robot's .rviz file and of `options` to `scene` (prepared by
// PrepareBagScene for the same `bag` and `stamp_at_zero`), when there are any: drawn in the scene's
// fixed frame, their topics read from `bag` ("" for none) as frames advance, their frames found
// through its TF (drawn through the orbit view or the calibrated camera alike). With a `cache`
// (and no `options`: those may be message files), displays it keeps are taken when they can show
// the stamp `moment_ns` next, and the displays made are kept in it, as is the TF they read. Throws urdfsnap::Error as
// DisplayOptions::MakeDisplays and tf::ReadBagTransforms do.
void AddSceneDisplays(const DisplayOptions& options, const std::string& bag, double stamp_at_zero, BagScene& scene,
                      Warnings& warnings, BagCache* cache = nullptr, std::int64_t moment_ns = 0);

}  // namespace urdfsnap::cli
