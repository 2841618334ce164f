// The one way into the render core, for every command, the live view and the C++ and Python
// APIs: a request (text as `urdfsnap render` takes it, or already typed: ResolvedRequest) is
// prepared once into {robot, settings, joint positions, a prepared render::RobotRenderer}; frames
// are then drawn from it, changing only what changes per frame (positions, view) as values, never
// by parsing text or reading files again. Each model is loaded once and each (model, displays)
// pair prepared once; all frames are drawn by the same gl::SceneRenderer per multisampling mode.
// Caches are owned by the session and bounded (the most recently used models and prepared robots
// are kept), so a long-running process that renders many robots does not grow.
//
//   request::RenderSession session;
//   request::Prepared arm = session.Prepare(request, request::CommandLineLabel, warnings);
//   image::Frame frame = session.Draw(arm);
//   arm.positions[2] = 0.5;                // a joint, radians
//   arm.settings.view.yaw += 0.1;          // the camera
//   image::Frame next = session.Draw(arm);
#pragma once

#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "gl/scene_renderer.h"
#include "image/image.h"
#include "render/robot_renderer.h"
#include "request/model_request.h"
#include "request/render_request.h"
#include "request/resolved_request.h"
#include "request/settings_parsing.h"

namespace urdfsnap::request {

// A request made ready to draw. The renderer belongs to the session that prepared it and stays
// valid until that session forgets the model (ForgetModels) or drops it from its cache (after
// kCachedRobots other (model, displays) pairs); the robot is shared and outlives both.
struct Prepared {
  std::shared_ptr<const model::Robot> robot;
  render::RenderSettings settings;  // the view as drawn: --fit applied, settings.fit then kNone
  std::vector<double> positions;    // one per robot->joints(): radians or metres, mimics resolved
  const render::RobotRenderer* renderer = nullptr;
};

// A frame with the robot that drew it (to name the links of its label image).
struct Rendered {
  image::Frame frame;
  std::shared_ptr<const model::Robot> robot;
};

class RenderSession {
 public:
  // backend: the GL backend of the contexts the session makes ({}: URDFSNAP_GL_BACKEND, else auto).
  explicit RenderSession(gl::BackendChoice backend = {});
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Prepares `request`: the model loaded (cached), an .rviz fixed frame outside the robot replaced
  // by the root link (with a warning), the joint values resolved (clamped unless asked not to),
  // the robot prepared for the displays (cached), the focal point moved to the target frame's
  // origin (a link; settings.target_frame) and settings.fit applied to the view for these positions. Warnings (the model's, clamped joints, ...) go to `warnings`. Throws
  // urdfsnap::Error for an unreadable model or mesh file, an unknown joint, ...
  Prepared Prepare(const ResolvedRequest& request, Warnings& warnings);

  // ResolveRequest, then Prepare: RViz's defaults, then the .rviz file, then the options given.
  // Throws urdfsnap::Error also for a bad option value (named through `label`) and an unreadable
  // .rviz or joint file.
  Prepared Prepare(const RenderRequest& request, const OptionLabel& label, Warnings& warnings);

  // Draws `prepared` (its positions, view, size, multisampling) into the images `outputs` asks
  // for. No file is read.
  image::Frame Draw(const Prepared& prepared, const image::FrameOutputs& outputs = {});

  // Prepare, then Draw, returning the robot with the frame.
  Rendered Render(const RenderRequest& request, const OptionLabel& label, Warnings& warnings,
                  const image::FrameOutputs& outputs = {});

  // The session's GL renderer for `samples` multisampling (made on first use, then kept), for
  // callers that draw a prepared robot themselves (animations).
  gl::SceneRenderer& GlRenderer(int samples);

  // Every file the session has read for `model`: the model file, xacro includes, YAML files,
  // meshes and textures (those of the displays rendered so far), without repeats.
  std::vector<std::string> Files(const ModelRequest& model) const;

  // Drops every loaded model and prepared robot, so that the next render reads the files again
  // (after an edit). GL contexts are kept.
  void ForgetModels();

  // The most models and prepared robots kept.
  static constexpr size_t kCachedModels = 8;
  static constexpr size_t kCachedRobots = 16;

 private:
  struct Model {
    ModelRequest request;
    LoadedModel loaded;
    Warnings warnings;   // given again to every render of the model
  };
  struct Robot {
    ModelRequest model;
    scene::SceneOptions options;
    std::unique_ptr<render::RobotRenderer> renderer;
    Warnings warnings;   // preparing it (missing meshes, plain paths), given again to every render
  };
  const Model& LoadedModelFor(const ModelRequest& request);
  const Robot& RobotFor(const ModelRequest& request, const Model& model, const scene::SceneOptions& options);

  std::list<Model> models_;   // most recently used first
  std::list<Robot> robots_;   // most recently used first
  const gl::BackendChoice backend_;
  std::map<int, std::unique_ptr<gl::SceneRenderer>> renderers_;
};

}  // namespace urdfsnap::request
