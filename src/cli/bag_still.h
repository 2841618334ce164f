// `render --bag FILE --at SECONDS`: one still of a recording as a player shows it at that moment.
// The robot is the bag's /robot_description when no MODEL is given; its joints take the latest
// /joint_states value at or before the time, and TF (the fixed frame, the TF display, a
// --camera-frame of the bag's TF) is looked up as tf2 does at that time. The still is frame 0 of a
// one-frame animation (animation::AnimationFrames), so that it is exactly what `animate --start
// SECONDS` draws first.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "animation/animation_frames.h"
#include "bag/joint_state_bag.h"
#include "bag/recorded_description.h"
#include "cli/bag_camera_image.h"
#include "cli/bag_scene.h"
#include "cli/display_options.h"
#include "common/warnings.h"
#include "image/image.h"
#include "motion/frame_plan.h"
#include "motion/frame_poses.h"
#include "motion/trajectory.h"
#include "request/render_request.h"
#include "request/render_session.h"

namespace urdfsnap::cli {

struct BagStillOptions {
  std::string bag;   // --bag; "" for a render without a bag
  std::string at;    // --at, checked as a number when the still is made
  std::string topic = bag::kDefaultJointStateTopic;
  std::string description_topic = bag::kDefaultDescriptionTopic;
  BagCameraOptions camera;   // --underlay-topic, --camera-info-topic

  // Adds --bag, --at, --topic, --description-topic, --underlay-topic and --camera-info-topic to
  // `command`.
  void AddOptions(CLI::App& command);
};

class BagStill {
 public:
  // Reads the bag's joint states and TF and prepares `request` (whose model is the robot to show)
  // at the time --at names: seconds from the first /joint_states stamp (as `animate --start`
  // counts), or a stamp (seconds since 1970, from 1e9 up). Throws urdfsnap::Error for a bad --at
  // (also one outside the recording) and as the bag's readers and RenderSession::Prepare do.
  // `model_from_bag`: the request's model is the description the bag recorded (see PrepareBagScene).
  // The message displays of the .rviz file and `displays` show the bag's messages up to the moment
  // (AddSceneDisplays). With --underlay-topic the camera's underlay is that topic's image at the
  // moment (AddBagUnderlay), with --camera-info-topic its calibration the topic's CameraInfo then
  // (ResolveWithBagCamera): what `animate` draws in a frame at the moment. A `cache` gives what an
  // earlier still of the bag read (its joint states, TF and displays) and keeps what this one reads
  // for the next.
  BagStill(const BagStillOptions& options, request::RenderSession& session, const request::RenderRequest& request,
           bool model_from_bag, const DisplayOptions& displays, Warnings& warnings, BagCache* cache = nullptr);
  BagStill(const BagStill&) = delete;
  BagStill& operator=(const BagStill&) = delete;

  // The robot as drawn: the moment's joint positions and the view (--fit applied to this moment).
  const request::Prepared& prepared() const { return scene_.robot; }
  // Its settings, for a caller that places the orbit view itself before Draw (snapshot's stored
  // camera).
  render::RenderSettings& settings() { return scene_.robot.settings; }

  // The still's scene in the orbit view (with its displays), for a renderer of the caller's. Call
  // it, or Draw, once: the displays have been fed up to the moment.
  scene::Scene Scene(Warnings& warnings) const;

  // Where the robot's fixed link is placed in the still's scene (by the bag's TF, the fixed frame):
  // what a calibrated camera on the robot is placed by (render::RobotRenderer::Render).
  Eigen::Isometry3d Place(Warnings& warnings) const;

  // Draws the still (with its displays) through `session`'s GL renderer into the images `outputs`
  // asks for. Call it once: the displays have been fed up to the moment.
  image::Frame Draw(request::RenderSession& session, const image::FrameOutputs& outputs, Warnings& warnings) const;

 private:
  motion::Trajectory trajectory_;
  motion::FramePlan plan_;
  BagScene scene_;
  std::optional<motion::FramePoses> poses_;
  std::optional<animation::AnimationFrames> frames_;
};

}  // namespace urdfsnap::cli
