// PrepareBagScene: the robot prepared from its root (and again from the fixed frame when that is
// a link other than the root), the bag's TF (read once: BagTransforms) for the root's placement,
// the TF display and the followed frame; the message displays.
#include "cli/bag_scene.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "common/error.h"
#include "request/display_frame.h"

namespace urdfsnap::cli {

animation::SceneAdditions BagScene::Additions() {
  return {root ? &*root : nullptr, tf ? &*tf : nullptr, follow ? &*follow : nullptr,
          displays ? &*displays : nullptr, underlay ? &*underlay : nullptr};
}

void PrepareBagScene(request::RenderSession& session, request::ResolvedRequest resolved, const std::string& bag,
                     double stamp_at_zero, bool model_from_bag, Warnings& warnings, BagScene& out, BagCache* cache) {
  // the description's relative mesh paths: from the bag's folder, not the temporary file's
  if (model_from_bag) {
    std::filesystem::path place(bag);
    if (!place.has_filename()) place = place.parent_path();   // a folder given as "run/"
    resolved.settings.scene.model_file = place.string();
  }
  const std::string fixed_frame = std::exchange(resolved.settings.scene.fixed_frame, "");
  const bool fixed_frame_given = std::exchange(resolved.fixed_frame_given, false);
  // the TF display is drawn here over the bag's frames, not by the robot's scene over its links,
  // and the target frame followed here frame by frame
  const scene::TfOptions tf_options = resolved.settings.scene.tf;
  resolved.settings.scene.tf.enabled = false;
  const std::string target_frame = std::exchange(resolved.settings.target_frame, "");
  out.robot = session.Prepare(resolved, warnings);
  const model::Robot& robot = *out.robot.robot;
  const std::string root = robot.links().front().name;
  // the bag's TF is read only when something shows it: a bag's /tf need not be readable otherwise
  const bool tf_fixed_frame = !bag.empty() && !fixed_frame.empty() && robot.FindLink(fixed_frame) < 0;
  const std::optional<render::CameraSettings>& camera = resolved.settings.camera;
  const bool tf_camera = !bag.empty() && camera && !camera->frame.empty() && robot.FindLink(camera->frame) < 0;
  const bool tf_shown = tf_fixed_frame || tf_camera || tf_options.enabled ||
                        (!target_frame.empty() && robot.FindLink(target_frame) < 0);
  out.transforms = !bag.empty() && tf_shown ? BagTransforms(bag, cache) : std::make_shared<const tf::TfBuffer>();
  if (tf_fixed_frame) {
    if (fixed_frame_given || out.transforms->Find(fixed_frame, root, 0)) {
      out.root.emplace(out.transforms, fixed_frame, root, stamp_at_zero, bag);
    } else {
      warnings.Add(resolved.rviz + ": Fixed Frame '" + fixed_frame + "' is neither a link of the robot nor a "
                   "frame that " + bag + "'s TF connects to it; using the root link '" + root + "'");
    }
  } else if (!fixed_frame.empty() && fixed_frame != root) {   // drawn from that link, as `render` does
    resolved.settings.scene.fixed_frame = fixed_frame;
    resolved.fixed_frame_given = fixed_frame_given;
    out.robot = session.Prepare(resolved, warnings);
  }
  if (tf_camera) out.camera_tf.emplace(out.transforms, camera->frame, root, stamp_at_zero, bag, "--camera-frame");
  const motion::TfDisplayFrames frames(*out.robot.robot, out.transforms, stamp_at_zero, bag);
  if (tf_options.enabled) out.tf.emplace(frames, tf_options);
  if (target_frame.empty()) return;
  const std::vector<std::string>& known = frames.names();
  if (resolved.target_frame_given || std::find(known.begin(), known.end(), target_frame) != known.end()) {
    out.follow.emplace(*out.robot.renderer, target_frame, bag.empty() ? std::nullopt : std::optional(frames));
  } else {
    warnings.Add(resolved.rviz + ": the view's Target Frame '" + target_frame + "' is neither a link of the robot "
                 "nor a frame of a bag's TF; the view orbits in the fixed frame");
  }
}

void AddSceneDisplays(const DisplayOptions& options, const std::string& bag, double stamp_at_zero, BagScene& scene,
                      Warnings& warnings, BagCache* cache, std::int64_t moment_ns) {
  const render::RenderSettings& s = scene.robot.settings;
  if (options.empty() && s.displays.empty()) return;
  // the scene's frame: where TF places the robot, else its fixed link
  const std::string fixed_frame = scene.root ? scene.root->fixed_frame()
                                  : s.scene.fixed_frame.empty() ? scene.robot.robot->links().front().name
                                                                : s.scene.fixed_frame;
  if (cache && !options.empty()) cache = nullptr;   // (message files)
  if (cache && cache->displays && cache->settings == s.displays && cache->fixed_frame == fixed_frame &&
      cache->stamp_at_zero == stamp_at_zero && cache->displays->CanShow(moment_ns)) {
    scene.displays = cache->displays;
    return;
  }
  // the scene reads the bag's TF only when it shows it; the displays' frames need it anyway
  std::shared_ptr<const tf::TfBuffer> transforms = scene.transforms;
  if (!bag.empty() && transforms->frames().empty()) {
    transforms = BagTransforms(bag, cache);
  }
  if (cache) cache->displays.reset();   // its reader thread and what its displays keep go first
  scene.displays = std::make_shared<animation::FrameDisplays>(
      options.MakeDisplays(s.displays, fixed_frame, request::MarkerResourcesFor(s.scene), warnings), bag,
      std::move(transforms), fixed_frame, stamp_at_zero);
  if (cache) {
    cache->settings = s.displays;
    cache->fixed_frame = fixed_frame;
    cache->stamp_at_zero = stamp_at_zero;
    cache->displays = scene.displays;
  }
}

}  // namespace urdfsnap::cli
