// `urdfsnap serve MODEL`: the live view. Prints the page's address as the first line on stdout,
// serves until SIGINT or SIGTERM, then stops cleanly (status 0). Reloads are logged on stderr.
#include <pthread.h>
#include <signal.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <memory>
#include <optional>
#include <thread>

#include "cli/bag_cache.h"
#include "cli/bag_model.h"
#include "cli/bag_still.h"
#include "cli/command.h"
#include "cli/gl_options.h"
#include "cli/model_source.h"
#include "cli/render_options.h"
#include "common/error.h"
#include "common/number_text.h"
#include "gl/gl_context.h"
#include "motion/trajectory_file.h"
#include "request/value_parsing.h"
#include "serve/loaded_server.h"

namespace urdfsnap::cli {

namespace {

struct ServeOptions {
  ModelSource model;
  RenderOptions render;
  GlOptions gl_options;
  std::string bind = "127.0.0.1";
  int port = 8765;
  std::string max_size = "4096x4096";
};

// SIGINT and SIGTERM blocked in this thread and so in every thread started after it; StopSignals
// below takes them with sigtimedwait.
sigset_t BlockStopSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  return signals;
}

std::string Url(const std::string& bind, int port) {
  const std::string host = bind.find(':') != std::string::npos ? "[" + bind + "]" : bind;
  return "http://" + host + ":" + std::to_string(port) + "/";
}

void LogReload(const serve::ModelState& state, const std::string& model) {
  if (state.robot) {
    std::fprintf(stderr, "urdfsnap: reloaded %s: robot '%s', %zu files watched\n", model.c_str(),
                 state.robot->name().c_str(), state.watched_files);
    for (const auto& warning : state.warnings) std::fprintf(stderr, "urdfsnap: warning: %s\n", warning.c_str());
  } else {
    std::fprintf(stderr, "urdfsnap: error: %s\n(still serving; the page shows this until the model loads again)\n",
                 state.error.c_str());
  }
}

// A bag served with a time slider: each moment drawn as `render --bag BAG --at T` draws it, the
// .rviz file's displays showing the bag's messages up to then; prepared through a session of its
// own (GL-free: the server draws the scene).
serve::RecordingView Recording(const std::string& bag, Warnings& warnings) {
  serve::RecordingView view;
  auto session = std::make_shared<request::RenderSession>();
  // what a request read of the bag, for the next: a slider dragged forward reads only the messages in between
  auto cache = std::make_shared<BagCache>();
  view.duration = BagJointStates(bag, bag::kDefaultJointStateTopic, warnings, cache.get()).EndTime();
  view.moment = [bag, session, cache](const request::RenderRequest& request, double at, Warnings& frame_warnings) {
    BagStillOptions moment;
    moment.bag = bag;
    moment.at = FormatNumber(at);
    try {
      const BagStill still(moment, *session, request, true, DisplayOptions{}, frame_warnings, cache.get());
      const request::Prepared& prepared = still.prepared();
      serve::RecordedMoment shown;
      shown.scene = still.Scene(frame_warnings);
      shown.settings = prepared.settings;
      if (prepared.settings.camera) {   // the camera on the robot at the moment, as BagStill::Draw places it
        shown.robot = prepared.renderer;
        shown.positions = prepared.positions;
        shown.X_SF = still.Place(frame_warnings);
      }
      return shown;
    } catch (...) {
      cache->displays.reset();   // a feed that failed gives nothing more: the next request starts again
      throw;
    }
  };
  return view;
}

void Run(ServeOptions& o) {
  // the server is a module (loaded_server.h): a missing one is the first thing reported
  const serve::ServerModule& server_module = serve::LoadServerModule();
  const sigset_t stop_signals = BlockStopSignals();
  std::signal(SIGPIPE, SIG_IGN);  // a client that goes away mid-response is not our end
  serve::ServerOptions options;
  options.backend = o.gl_options.Choice();
  const auto gl_loading = gl::StartLoadingGl(options.backend.backend);
  options.base = o.render.request;
  options.base.model = o.model.ToRequest();
  // a bag: its recorded description is the model, played through with a time slider
  Warnings warnings;
  std::optional<BagModel> bag_model;
  if (motion::IsBag(o.model.path)) {
    bag_model.emplace(o.model.path, bag::kDefaultDescriptionTopic);
    options.base.model.path = bag_model->path();
    options.recording = Recording(o.model.path, warnings);
  }
  o.render.ParseJointWords();
  options.base.joints = o.render.request.joints;
  options.bind = o.bind;
  options.port = o.port;
  options.max_size = request::ParseImageSize(o.max_size, "--max-size");
  options.on_reload = [model = o.model.path](const serve::ModelState& state) { LogReload(state, model); };

  if (!server_module.is_loopback(o.bind)) {
    warnings.Add("--bind " + o.bind + ": anyone who can reach this address sees the model and "
                 "its pictures (the server has no login)");
  }
  std::unique_ptr<serve::LoadedServer> server;
  try {
    server = std::make_unique<serve::LoadedServer>(options, warnings);
  } catch (...) {
    PrintWarningsBeforeError(warnings);
    throw;
  }
  PrintWarnings(warnings);
  const int port = server->Bind();
  WriteToStdout("urdfsnap: serving " + Url(o.bind, port) + "\n");

  std::jthread signal_waiter([&](std::stop_token stop) {
    const timespec tick{0, 200'000'000};
    bool signalled = false;  // a signal may come before Run() serves: stop it once it does
    while (!stop.stop_requested()) {
      if (signalled && server->Stop()) return;
      if (signalled) std::this_thread::sleep_for(std::chrono::milliseconds(10));
      else signalled = sigtimedwait(&stop_signals, nullptr, &tick) > 0;
    }
  });
  server->Run();
  std::fprintf(stderr, "urdfsnap: stopped\n");
}

}  // namespace

void AddServeCommand(CLI::App& app) {
  auto o = std::make_shared<ServeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "serve", "Live view in the browser: joint sliders and an orbit camera, rendered by urdfsnap, "
               "reloading as the model's files change");
  o->model.AddOptions(*cmd);
  cmd->add_option("--port", o->port, "TCP port (default 8765; 0 picks a free one)");
  cmd->add_option("--bind", o->bind,
                  "address to listen on (default 127.0.0.1: this machine only; another address "
                  "lets anyone who can reach it see the model)");
  cmd->add_option("--max-size", o->max_size, "largest image a request may ask for (default 4096x4096)");
  o->render.AddOptions(*cmd);
  o->gl_options.AddOptions(*cmd);
  cmd->footer(
      "\nThe options after MODEL set the page's initial view and pose. Over SSH:\n"
      "  ssh -L 8765:127.0.0.1:8765 HOST urdfsnap serve MODEL   then open http://localhost:8765/\n"
      "HTTP API: GET /render.png?yaw=0.5&size=800x600&no-grid&j.NAME=VALUE (render's option names),\n"
      "GET /api/robot (joints with joint_state_publisher's ranges and defaults), /api/view, /api/status,\n"
      "/api/fit?...&link=NAME (the view that frames the robot or a link). A model that does not load is\n"
      "served as its error until an edit mends it.\n");
  cmd->callback([o] { Run(*o); });
}

}  // namespace urdfsnap::cli
