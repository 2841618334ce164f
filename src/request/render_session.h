// The text front of the render core: renders RenderRequests (one render in `urdfsnap render`'s
// words) one after another in one process. Each request's text is parsed once into typed
// settings; each model is loaded once and each (model, displays) pair prepared once as a
// render::RobotRenderer; all frames are drawn by the same gl::Renderer per multisampling mode.
// Caches are owned by the session and bounded (the most recently used models and prepared robots
// are kept), so a long-running process that renders many robots does not grow.
#pragma once

#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "gl/renderer.h"
#include "image/image.h"
#include "render/robot_renderer.h"
#include "request/model_request.h"
#include "request/render_request.h"
#include "request/settings_parsing.h"

namespace urdfsnap::request {

// A request made ready to draw: resolved settings (--fit applied), joint positions (one per robot
// joint, mimics resolved), the prepared robot (owned by the session that prepared it, valid while
// it stays in the session's cache).
struct Prepared {
  render::RenderSettings settings;
  std::vector<double> positions;
  const render::RobotRenderer* renderer = nullptr;
};

class RenderSession {
 public:
  // backend: the GL backend of the contexts the session makes ({}: URDFSNAP_GL_BACKEND, else auto).
  explicit RenderSession(gl::BackendChoice backend = {});
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Renders `request`: RViz's defaults, then the .rviz file, then the options given; the images
  // `outputs` asks for. Warnings (the model's, clamped joints, ...) go to `warnings`. Throws
  // urdfsnap::Error for a bad option value (named through `label`), an unreadable model, joint or
  // mesh file, an unknown joint, ...
  image::Frame Render(const RenderRequest& request, const OptionLabel& label, Warnings& warnings,
                      const image::FrameOutputs& outputs = {});

  // Everything Render does before it draws: settings parsed and resolved, the model loaded and the
  // robot prepared (cached), joint values resolved. Throws urdfsnap::Error as Render does.
  Prepared Prepare(const RenderRequest& request, const OptionLabel& label, Warnings& warnings);

  // Draws `prepared` into the images `outputs` asks for; reads no file.
  image::Frame Draw(const Prepared& prepared, const image::FrameOutputs& outputs = {});

  // The settings Render uses for `request`, resolved: the view as the frame shows it (--fit applied,
  // `fit` then kNone), an .rviz fixed frame outside the robot replaced by the root link. Loads and
  // prepares the robot as Render does (cached). Throws urdfsnap::Error as Render does.
  render::RenderSettings ResolveSettings(const RenderRequest& request, const OptionLabel& label, Warnings& warnings);

  // The robot `model` names, loaded once and cached as for Render (its warnings go to `warnings`
  // each time). Throws urdfsnap::Error as Render does for an unreadable model.
  std::shared_ptr<const model::Robot> LoadRobot(const ModelRequest& model, Warnings& warnings);

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
  gl::Renderer& RendererFor(int samples);

  std::list<Model> models_;   // most recently used first
  std::list<Robot> robots_;   // most recently used first
  const gl::BackendChoice backend_;
  std::map<int, std::unique_ptr<gl::Renderer>> renderers_;
};

}  // namespace urdfsnap::request
