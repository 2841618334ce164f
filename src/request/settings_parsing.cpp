// The .rviz file read over RViz's defaults; each option's text checked and applied over them.
#include "request/settings_parsing.h"

#include <numbers>

#include "request/camera_parsing.h"
#include "request/rviz_config.h"
#include "request/value_parsing.h"
#include "scene/tf_markers.h"

namespace urdfsnap::request {

namespace {

void ApplyView(const RenderRequest& r, const OptionLabel& label, scene::OrbitView& view) {
  if (!r.yaw.empty()) view.yaw = ParseFinite(r.yaw, label("yaw"));
  if (!r.pitch.empty()) view.pitch = ParseFinite(r.pitch, label("pitch"));
  if (!r.distance.empty()) view.distance = ParseInRange(r.distance, label("distance"), 0.01, 1e6);
  if (!r.focal.empty()) view.focal = ParseVector3(r.focal, label("focal"));
  // RViz's Field of View property range, 0.001 to π/2 rad (orbit_view_controller.cpp L81-85)
  if (!r.fov.empty()) view.fov_y = ParseInRange(r.fov, label("fov"), 0.06, 90) * std::numbers::pi / 180;
}

void ApplyScene(const RenderRequest& r, const OptionLabel& label, scene::SceneOptions& scene) {
  if (!r.fixed_frame.empty()) scene.fixed_frame = r.fixed_frame;
  if (!r.background.empty()) {
    scene.background = ParseColour(r.background, label("background"));
    scene.tf.name_colour = scene::NameColourOn(scene.background);
  }
  if (!r.alpha.empty()) scene.alpha = ParseInRange(r.alpha, label("alpha"), 0, 1);
  if (r.collision) scene.show_collision = true;
  if (r.no_visual) scene.show_visual = false;
  if (r.no_grid) scene.grid.enabled = false;
  if (r.tf) scene.tf.enabled = true;
  if (r.no_tf_names) scene.tf.show_names = false;
  if (r.no_tf_axes) scene.tf.show_axes = false;
  if (r.no_tf_arrows) scene.tf.show_arrows = false;
  if (!r.tf_scale.empty()) scene.tf.marker_scale = ParseInRange(r.tf_scale, label("tf-scale"), 0, 1e6);
  scene.allow_missing_meshes = r.allow_missing_meshes;
  scene.model_file = r.model.path;
  scene.packages = r.model.packages;
}

}  // namespace

std::string CommandLineLabel(std::string_view name) { return "--" + std::string(name); }

render::Fit FitOf(const RenderRequest& r) {
  if (!r.fit) return render::Fit::kNone;
  return r.focal.empty() ? render::Fit::kFit : render::Fit::kKeepFocal;
}

render::RenderSettings ReadBaseSettings(const RenderRequest& r, Warnings& warnings) {
  render::RenderSettings settings;
  if (!r.rviz.empty()) {
    const RvizConfig config = ReadRvizConfig(r.rviz, {settings.scene, settings.view, "", {}}, warnings);
    settings.scene = config.scene;
    settings.view = config.view;
    settings.target_frame = config.target_frame;
    settings.displays = config.displays;
  }
  return settings;
}

void ApplyOptions(const RenderRequest& r, const CameraFiles& camera_files, const OptionLabel& label,
                  render::RenderSettings& settings) {
  settings.size = ParseImageSize(r.size.empty() ? kDefaultSize : r.size, label("size"));
  ApplyView(r, label, settings.view);
  ApplyScene(r, label, settings.scene);
  if (!r.follow.empty()) settings.target_frame = r.follow;
  settings.samples = r.no_aa ? 0 : 4;
  settings.fit = FitOf(r);
  if (!r.fit_margin.empty()) settings.fit_margin = ParseFitMargin(r.fit_margin, label("fit-margin"), settings.size);
  // the calibrated camera, if any
  settings.camera = ParseCameraSettings(r, camera_files, label, settings);
}

void WarnOfOptionsWithoutEffect(const RenderRequest& r, const OptionLabel& label, Warnings& warnings) {
  // the TF display's options, when neither --tf nor an .rviz config (which may show TF) turns it on
  if (!r.tf && r.rviz.empty()) {
    for (const auto& [given, name] : {std::pair{!r.tf_scale.empty(), "tf-scale"}, {r.no_tf_names, "no-tf-names"},
                                      {r.no_tf_axes, "no-tf-axes"}, {r.no_tf_arrows, "no-tf-arrows"}}) {
      if (given) WarnIgnored(warnings, label(name), "the TF display is off (" + label("tf") + " shows it)");
    }
  }
  if (!r.fit && !r.fit_margin.empty()) {
    WarnIgnored(warnings, label("fit-margin") + " " + r.fit_margin,
                "it is the border " + label("fit") + " leaves, and " + label("fit") + " is not given");
  }
  if (r.fit && !r.distance.empty()) {
    WarnIgnored(warnings, label("distance") + " " + r.distance,
                label("fit") + " chooses the distance that frames the robot");
  }
  // a camera replaces the orbit view (and --camera-info its field of view); --fit is an error there
  if (r.camera_info.empty() && r.camera_frame.empty() && r.camera_pose.empty()) return;
  if (!r.camera_info.empty() && !r.size.empty()) {
    WarnIgnored(warnings, label("size") + " " + r.size, "the size comes from the calibration (" + label("camera-info") + ")");
  }
  for (const auto& [given, name] : {std::pair{!r.yaw.empty(), "yaw"}, {!r.pitch.empty(), "pitch"},
                                    {!r.distance.empty(), "distance"}, {!r.focal.empty(), "focal"},
                                    {!r.follow.empty(), "follow"}, {!r.fov.empty() && !r.camera_info.empty(), "fov"}}) {
    if (given) {
      WarnIgnored(warnings, label(name), std::string("the camera (") + label("camera-info") + ", " +
                                             label("camera-frame") + ", " + label("camera-pose") +
                                             ") replaces the orbit view" +
                                             (name == std::string("fov") ? " and its field of view" : ""));
    }
  }
}

render::RenderSettings ParseRenderSettings(const RenderRequest& r, const OptionLabel& label,
                                           Warnings& warnings) {
  render::RenderSettings settings = ReadBaseSettings(r, warnings);
  ApplyOptions(r, ReadCameraFiles(r), label, settings);
  WarnOfOptionsWithoutEffect(r, label, warnings);
  return settings;
}

}  // namespace urdfsnap::request
