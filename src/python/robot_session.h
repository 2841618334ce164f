// What one Python `urdfsnap.Robot` holds, in C++ and without Python: a request::RenderSession (the
// one way into the core every command takes) with the robot loaded, and the settings that
// Robot.render's keyword arguments make (parsed by the request stage, as the command line's
// options are). The session keeps the robot prepared for the displays asked for and the GL
// renderers that draw it for the next call. The pybind11 glue (module.cpp) only converts to and from Python.
// The pixels are those of `urdfsnap render` with the same options: the same typed core
// (model::ResolveJointPositions, render::RobotRenderer, gl::SceneRenderer) does the work.
//
// Not thread-safe by itself: the glue holds the session's mutex while it draws.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/warnings.h"
#include "dataset/frame_extras.h"
#include "gl/backend.h"
#include "gl/scene_renderer.h"
#include "image/image.h"
#include "model/joint_values.h"
#include "model/robot.h"
#include "render/render_settings.h"
#include "render/robot_renderer.h"
#include "request/model_request.h"
#include "request/render_request.h"
#include "request/render_session.h"

namespace urdfsnap::python {

// One Robot.render or render_many call: the view and display keywords in the words of `urdfsnap
// render` (request::RenderRequest, parsed and checked by the request stage as the command line's
// options are, so that the same keywords give the same settings and pixels), and what is not a
// render option there.
struct RenderCall {
  request::RenderRequest request;   // its model is filled in by RobotSession::Settings
  bool depth = false, labels = false;
  dataset::ExtrasWanted extras;     // mask, keypoints
  std::optional<image::Image> underlay;   // a camera image given as an array (else request.underlay's file)
  std::string gl_backend = "auto";
};

// "auto" (URDFSNAP_GL_BACKEND when set, as for a command given no --gl-backend), "osmesa", "egl".
std::optional<gl::Backend> BackendKeyword(const std::string& name);

class RobotSession {
 public:
  // Loads the robot (xacro expanded when the file is xacro or args are given). Throws
  // urdfsnap::Error with the command line's message for an unreadable or invalid model.
  explicit RobotSession(request::ModelRequest model);

  const request::ModelRequest& model() const { return model_; }
  const model::Robot& robot() const { return *robot_; }
  // The warnings of loading the model (shown once, when it is loaded).
  const Warnings& load_warnings() const { return load_warnings_; }
  // The joints a value moves (Robot.joint_names): the columns of render_many's positions.
  const std::vector<std::string>& movable_joints() const { return movable_joints_; }

  // The settings `call` asks for, for this robot, as `urdfsnap render` parses its options (RViz's
  // defaults, an .rviz file, the options given), with call.underlay as the camera's image. Throws
  // urdfsnap::Error naming the keyword ("distance '0': expected a value from 0.01 to 1000000");
  // warnings go to `warnings`.
  render::RenderSettings Settings(const RenderCall& call, Warnings& warnings) const;

  // One position per robot().joints() for the values `given` (names checked, limits clamped
  // unless `clamp` is false, mimic joints following), as `urdfsnap render -j` resolves them.
  std::vector<double> Positions(const model::NamedValues& given, bool clamp, Warnings& warnings) const;

  // Draws each of `poses` (from Positions) with `settings`: through settings.camera when set, else
  // the orbit view, `fit` framing all poses with one camera, as animate does. `deliver(k, frame,
  // extras)` receives each frame with the mask and keypoints `extras` asks for (the keypoints
  // through the orbit view as a camera when no camera is set). Does no file I/O after the first
  // call for a display setting (meshes are loaded once).
  template <typename Deliver>
  void Render(const render::RenderSettings& settings, std::optional<gl::Backend> backend,
              const std::vector<std::vector<double>>& poses, const image::FrameOutputs& outputs,
              const dataset::ExtrasWanted& extras, Deliver&& deliver, Warnings& warnings);

  std::mutex& mutex() { return mutex_; }

 private:
  request::ModelRequest model_;
  Warnings load_warnings_;
  request::RenderSession session_;   // the model, the prepared robots, the GL renderers
  std::shared_ptr<const model::Robot> robot_;
  std::vector<std::string> movable_joints_;
  std::mutex mutex_;
};

template <typename Deliver>
void RobotSession::Render(const render::RenderSettings& settings, std::optional<gl::Backend> backend,
                          const std::vector<std::vector<double>>& poses, const image::FrameOutputs& outputs,
                          const dataset::ExtrasWanted& extras, Deliver&& deliver, Warnings& warnings) {
  const render::RobotRenderer& renderer = session_.PreparedRobot(model_, settings.scene, warnings);
  render::RenderSettings drawn = settings;
  drawn.view = renderer.FitView(settings.fit, settings.fit_margin, settings.view, settings.size,
                                static_cast<int>(poses.size()), [&](int k) { return poses[k]; });
  drawn.fit = render::Fit::kNone;
  const render::CameraSettings camera =
      drawn.camera ? *drawn.camera : render::OrbitCamera(drawn.view, drawn.size.width, drawn.size.height);
  const image::FrameOutputs needed = dataset::OutputsFor(outputs, extras);
  gl::SceneRenderer& gl = session_.GlRenderer(settings.samples, backend);
  // the next call, or the destructor, may come from another thread
  struct Release {
    gl::SceneRenderer& gl;
    ~Release() { gl.ReleaseContext(); }
  } release{gl};
  for (size_t k = 0; k < poses.size(); ++k) {
    image::Frame frame = renderer.Render(gl, poses[k], drawn, needed);
    dataset::FrameExtras made = dataset::MakeFrameExtras(extras, renderer, poses[k], camera, frame);
    deliver(k, std::move(frame), std::move(made));
  }
}

}  // namespace urdfsnap::python
