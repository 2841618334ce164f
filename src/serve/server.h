// The live view's HTTP server (cpp-httplib): the embedded page, GET /render.png in render's
// option words (and at=SECONDS, a moment of a recording), /api/robot, /api/view, /api/status and /api/fit, with the model reloaded as its
// files change.
//
// It answers nothing else: no URL names a file, every response is the page, a rendered image or
// JSON/text made here. Limits: request bodies of 4 KiB (a GET has none), request lines and
// header lines of 8 KiB (the library's), a whole request in 64 KiB and 5 s (idle time included),
// 8 connections waiting for a request per client address and 24 in all (the longest waiting is
// closed for a new one: a slowloris), images up to ServerOptions::max_size, one render at a
// time (on one render thread) with at most max_waiting_renders more waiting (the rest get 503 at
// once), a fixed pool of connection threads. Bound to a loopback address it answers only requests that name a loopback
// host (so a web page elsewhere cannot reach it by DNS rebinding).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "gl/backend.h"
#include "render/render_settings.h"
#include "request/render_request.h"
#include "scene/scene.h"
#include "serve/connection_limits.h"
#include "serve/live_model.h"

namespace urdfsnap::render {
class RobotRenderer;
}  // namespace urdfsnap::render

namespace urdfsnap::serve {

// A moment of a recording as a scene to draw (GL-free) and the settings to draw it with.
struct RecordedMoment {
  scene::Scene scene;
  render::RenderSettings settings;
  // Through a calibrated camera (settings.camera): the robot that carries it (valid until the
  // recording's next moment), its joint positions and where its fixed link is placed in the scene,
  // for render::RobotRenderer::Render; unset for the orbit view.
  const render::RobotRenderer* robot = nullptr;
  std::vector<double> positions;
  Eigen::Isometry3d X_SF = Eigen::Isometry3d::Identity();
};

// A recording the page plays through with a time slider (`urdfsnap serve run.mcap`): its length,
// and the moment `at` seconds from its first joint state for a request, as `render --bag --at`
// draws it (the recorded joint states and TF, the .rviz file's displays showing the bag's messages
// up to then). The command supplies it: the server knows no bags, and draws the scene itself (its
// GL is the server module's own).
struct RecordingView {
  double duration = 0;
  std::function<RecordedMoment(const request::RenderRequest& request, double at, Warnings& warnings)> moment;
};

struct ServerOptions {
  std::string bind = "127.0.0.1";  // address to listen on
  int port = 8765;                 // 0: any free port
  // the model and the options `urdfsnap serve` was given: every frame starts from them
  request::RenderRequest base;
  render::ImageSize max_size{4096, 4096};  // largest frame, per side
  int max_waiting_renders = 8;   // requests that wait for the renderer; more get 503
  int threads = 32;              // connections served at once (keep-alive ones included)
  // connections waiting for a request, per client and in all (more than threads - total are
  // left for answering), and the time and bytes of one request and response
  ConnectionLimits connection_limits;
  StreamLimits stream_limits;
  std::chrono::milliseconds watch_interval{250};  // how often the model's files are looked at
  // the GL backend of the one renderer, made with the first frame
  gl::BackendChoice backend;
  // called after each reload of the model (not the first load), from the watching thread
  std::function<void(const ModelState&)> on_reload;
  // set when the model is a recording: /render.png then takes at=SECONDS
  std::optional<RecordingView> recording;
};

// True when `address` is a loopback address or name (127.x.x.x, ::1, localhost).
bool IsLoopback(const std::string& address);

class Server {
 public:
  // Loads the model and renders the initial view once (which checks the options and loads the
  // meshes); its warnings go to `warnings`. Throws urdfsnap::Error as `urdfsnap render` would for
  // an option value. A model that does not load (its files, or the .rviz and joint files) is a
  // warning: the server serves its error until an edit mends it.
  Server(ServerOptions options, Warnings& warnings);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Opens the listening socket; returns the port. Throws urdfsnap::Error when it cannot.
  int Bind();
  // Serves until Stop(); watches the model's files meanwhile.
  void Run();
  // Ends Run() (no new connections; requests being answered finish; thread-safe) and returns true
  // once Run() is serving; before that it does nothing and returns
  // false (cpp-httplib ignores a stop that comes before its accept loop), so call it until true.
  bool Stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace urdfsnap::serve
