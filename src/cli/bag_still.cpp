// BagStill: the bag's trajectory read, a one-frame plan at --at, the robot prepared through
// PrepareBagScene and fitted by AnimationFrames, drawn with its TF display and message displays.
#include "cli/bag_still.h"

#include <cmath>
#include <utility>

#include "cli/bag_camera_image.h"
#include "common/error.h"
#include "common/number_text.h"
#include "image/png_reader.h"
#include "request/value_parsing.h"

namespace urdfsnap::cli {

void BagStillOptions::AddOptions(CLI::App& command) {
  command.add_option("--bag", bag,
                     "draw one moment of a recording (.mcap or .db3 file, or a rosbag2 folder): the "
                     "joints' latest /joint_states values at or before --at and TF at --at; the robot "
                     "is MODEL, or without one the bag's robot description. A MODEL that is a bag is "
                     "taken for --bag (default: no bag)");
  command.add_option("--at", at,
                     "with --bag, the moment drawn: seconds from the first /joint_states stamp (as "
                     "`animate --start` counts), or a stamp (seconds since 1970, from 1e9 up) "
                     "(default 0)");
  command.add_option("--topic", topic, "with --bag, its sensor_msgs/msg/JointState topic (default /joint_states)");
  command.add_option("--description-topic", description_topic,
                     "with --bag and no MODEL, the std_msgs/msg/String topic whose first message is "
                     "the robot description (default /robot_description)");
  camera.AddOptions(command, "--at");
}

BagStill::BagStill(const BagStillOptions& o, request::RenderSession& session, const request::RenderRequest& r,
                   bool model_from_bag, const DisplayOptions& displays, Warnings& warnings, BagCache* cache) {
  trajectory_ = BagJointStates(o.bag, o.topic, warnings, cache);
  const double at = o.at.empty() ? 0 : request::ParseFinite(o.at, "--at");
  plan_.trajectory_start = motion::TrajectorySeconds(trajectory_, at, "--at");
  if (plan_.trajectory_start < 0 || plan_.trajectory_start > trajectory_.EndTime()) {
    throw Error("--at " + FormatNumber(at) + " is outside " + o.bag + ", whose '" + o.topic + "' lasts " +
                FormatNumber(trajectory_.EndTime()) + " s from its first message");
  }
  // the moment as a stamp, nanoseconds since 1970
  const auto moment_ns =
      static_cast<std::int64_t>(std::llround((trajectory_.stamp_at_zero.value_or(0) + plan_.trajectory_start) * 1e9));
  request::ResolvedRequest resolved = ResolveWithBagCamera(r, o.camera, o.bag, moment_ns, warnings);
  const render::Fit fit = std::exchange(resolved.settings.fit, render::Fit::kNone);
  const model::NamedValues joints = resolved.joints;   // -j and --joints: for joints the bag does not name
  const motion::JointRules rules{resolved.clamp};
  PrepareBagScene(session, std::move(resolved), o.bag, trajectory_.stamp_at_zero.value_or(0), model_from_bag,
                  warnings, scene_, cache);
  AddSceneDisplays(displays, o.bag, trajectory_.stamp_at_zero.value_or(0), scene_, warnings, cache, moment_ns);
  AddBagUnderlay(o.camera, r, o.bag, trajectory_.stamp_at_zero.value_or(0), scene_);
  request::Prepared& prepared = scene_.robot;
  poses_.emplace(*prepared.robot, trajectory_, joints, rules, warnings);
  const render::RenderSettings& s = prepared.settings;
  frames_.emplace(*prepared.renderer, plan_, *poses_,
                  animation::CameraRequest{s.view, s.size, fit, s.fit_margin, false, s.camera,
                                           scene_.camera_tf ? &*scene_.camera_tf : nullptr},
                  warnings, scene_.Additions());
  prepared.positions = frames_->Positions(0, warnings);
  prepared.settings.view = frames_->View(0);
  // a camera in the bag's TF placed at the moment, the bag's camera image of the moment behind it
  prepared.settings.camera = frames_->Camera(0, warnings);
}

scene::Scene BagStill::Scene(Warnings& warnings) const {
  return frames_->Scene(*scene_.robot.renderer, 0, warnings);
}

Eigen::Isometry3d BagStill::Place(Warnings& warnings) const { return frames_->Place(0, warnings); }

image::Frame BagStill::Draw(request::RenderSession& session, const image::FrameOutputs& outputs,
                            Warnings& warnings) const {
  const request::Prepared& p = scene_.robot;
  gl::SceneRenderer& gl = session.GlRenderer(p.settings.samples);
  if (p.settings.camera) {   // the scene (the displays, the TF display) through the camera on the placed robot
    return p.renderer->Render(gl, Scene(warnings), Place(warnings), p.positions, *p.settings.camera, outputs);
  }
  return gl.Render(Scene(warnings), p.settings.view, p.settings.size.width, p.settings.size.height, outputs);
}

}  // namespace urdfsnap::cli
