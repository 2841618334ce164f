// Routes, limits and the watching thread of the live view's server.
#include "serve/server.h"

#include <arpa/inet.h>
#include <sys/socket.h>
#include <unistd.h>

#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <stop_token>
#include <thread>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "serve/client_connections.h"
#include "serve/deadline_stream.h"
#include "serve/embedded_page.h"
#include "serve/frame_source.h"
#include "serve/render_thread.h"
#include "serve/initial_view.h"
#include "serve/query_request.h"
#include "serve/page_robot_json.h"
#include "request/resolved_request.h"
#include "request/value_parsing.h"

namespace urdfsnap::serve {

namespace {

constexpr const char* kErrorPrefix = "urdfsnap: error: ";

// The host name of a Host header ("localhost:8765" → "localhost", "[::1]:80" → "::1").
std::string HostName(const std::string& host) {
  if (host.starts_with("[")) return host.substr(1, host.find(']') - 1);
  return host.substr(0, host.find(':'));
}

void SetText(httplib::Response& res, int status, const std::string& text) {
  res.status = status;
  res.set_content(text + "\n", "text/plain; charset=utf-8");
}

void SetJson(httplib::Response& res, int status, const nlohmann::json& json) {
  res.status = status;
  res.set_content(json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

// The words for the statuses the library answers by itself.
std::string Reason(int status) {
  switch (status) {
    case 400: return "bad request";
    case 404: return "not found (this server has its page, /render.png and /api/{robot,view,status,fit})";
    case 405: return "method not allowed";
    case 413: return "request body too large";
    case 414: return "URI too long";
    default: return "error";
  }
}

// The connection being served on this thread (0: none), for the pre-routing handler.
thread_local std::uint64_t current_connection = 0;

// cpp-httplib's server with its per-connection loop replaced (the library lets a subclass do so):
// each request read through a DeadlineStream (time and byte budgets), each connection counted in
// ClientConnections while it waits for a request (so idle ones beyond the limits are closed).
class GuardedHttpServer : public httplib::Server {
 public:
  GuardedHttpServer(ConnectionLimits connection_limits, StreamLimits stream_limits)
      : connections_(connection_limits), stream_limits_(stream_limits) {}

  // The request of this thread's connection has arrived: it is being answered, not waiting.
  void RequestArrived() {
    if (current_connection != 0) connections_.Answer(current_connection);
  }

 private:
  bool process_and_close_socket(socket_t sock) override {
    DeadlineStream stream(sock, svr_sock_, stream_limits_);
    std::string client;
    int port = 0;
    stream.get_remote_ip_and_port(client, port);
    current_connection = connections_.Open(client, sock);
    bool ok = true;
    for (std::size_t count = keep_alive_max_count_; ok && count > 0; --count) {
      if (count != keep_alive_max_count_) {
        stream.BeginRequest();
        connections_.Wait(current_connection);
      }
      if (!stream.WaitForRequest()) break;
      bool closed = false;
      ok = process_request(stream, count == 1, closed, nullptr);
      if (closed || stream.spent()) break;
    }
    connections_.Close(current_connection);
    current_connection = 0;
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return ok;
  }

  ClientConnections connections_;
  StreamLimits stream_limits_;
};

// Throws urdfsnap::Error for an option value no edit of the model's files can mend (--yaw x): those
// end `urdfsnap serve` at once, as `render` would; the .rviz and joint files are read with the
// model, and like it served as an error until they load.
void CheckOptionValues(request::RenderRequest base) {
  base.rviz.clear();
  base.joint_file.clear();
  request::ResolveRequest(base, request::RequestFiles{}, request::CommandLineLabel);
}

// How the page names the calibrated camera it shows, "" exactly when it shows the orbit view (no
// --camera-info, --camera-frame or --camera-pose): the calibration file and where the camera is,
// as the command line gave them.
std::string CameraViewText(const request::RenderRequest& base) {
  std::string text = std::filesystem::path(base.camera_info).filename().string();
  const std::string at = !base.camera_frame.empty() ? "frame " + base.camera_frame
                         : !base.camera_pose.empty() ? "pose " + base.camera_pose
                                                     : "";
  if (!at.empty()) text += (text.empty() ? "" : " at ") + at;
  return text;
}

}  // namespace

bool IsLoopback(const std::string& address) {
  if (address == "localhost" || address == "::1") return true;
  in_addr ip4{};
  return inet_pton(AF_INET, address.c_str(), &ip4) == 1 && (ntohl(ip4.s_addr) >> 24) == 127;
}

struct Server::Impl {
  explicit Impl(ServerOptions o) : options(std::move(o)), live(options.base.model.path) {}

  ServerOptions options;
  LiveModel live;
  // /api/view, made by the first load that succeeds ("" until then: a model broken at start-up is
  // served as its error until it is fixed)
  std::mutex initial_view_mutex;
  std::string initial_view;
  GuardedHttpServer http{options.connection_limits, options.stream_limits};

  // one frame at a time, a bounded number waiting (last: it ends first, before what it uses)
  RenderThread renderer{static_cast<size_t>(options.max_waiting_renders), options.backend};

  // (re)loads the model and checks that its initial view renders, between two frames; the first
  // good load also resolves the page's starting view (its warnings to `warnings`)
  std::shared_ptr<const ModelState> Reload(Warnings& warnings) {
    std::shared_ptr<const ModelState> state;
    renderer.Run([&](FrameSource& frames) {
      state = live.Load([&] {
        WatchedModel model = frames.Reload(options.base);
        const std::lock_guard lock(initial_view_mutex);
        if (initial_view.empty()) initial_view = InitialViewJson(options.base, frames.Start(warnings));
        return model;
      });
    });
    return state;
  }

  void Watch(std::stop_token stop) {
    std::mutex mutex;
    std::condition_variable_any wake;
    for (;;) {
      std::unique_lock lock(mutex);
      wake.wait_for(lock, stop, options.watch_interval, [] { return false; });
      if (stop.stop_requested()) return;
      if (!live.NeedsLoad()) continue;
      Warnings warnings;   // the starting view's, after a broken start: the model's are in the state
      const std::shared_ptr<const ModelState> state = Reload(warnings);
      if (options.on_reload) options.on_reload(*state);
    }
  }

  void Page(const std::string& name, const char* type, httplib::Response& res) {
    res.set_content(std::string(EmbeddedPageFile(name)), type);
  }

  void RenderFrame(const httplib::Request& req, httplib::Response& res) {
    const std::shared_ptr<const ModelState> state = live.State();
    if (!state->robot) return SetText(res, 422, kErrorPrefix + state->error);
    request::RenderRequest r;
    std::optional<double> at;   // a moment of the recording
    try {
      Query query = req.params;
      if (const auto found = query.find("at"); found != query.end()) {
        if (!options.recording) throw Error("at: a moment of a recording; urdfsnap serve was given no bag");
        at = request::ParseFinite(found->second, "at");
        query.erase(found);
      }
      r = RequestFromQuery(query, options.base);
      const std::string size_text = r.size.empty() ? request::kDefaultSize : r.size;
      const render::ImageSize size = request::ParseImageSize(size_text, "--size");
      if (size.width > options.max_size.width || size.height > options.max_size.height) {
        throw Error("--size '" + size_text + "': urdfsnap serve renders at most " +
                    std::to_string(options.max_size.width) + "x" +
                    std::to_string(options.max_size.height) + " pixels (--max-size)");
      }
    } catch (const Error& e) {
      return SetText(res, 400, kErrorPrefix + std::string(e.what()));
    }
    int generation = 0;
    std::string png;
    const auto start = std::chrono::steady_clock::now();
    try {
      const bool ran = renderer.TryRun([&](FrameSource& frames) {
        generation = live.State()->generation;
        Warnings warnings;
        png = at ? frames.RenderMomentPng(*options.recording, r, *at, warnings) : frames.RenderPng(r, warnings);
      });
      if (!ran) {
        res.set_header("Retry-After", "1");
        return SetText(res, 503, "urdfsnap serve: busy rendering; try again");
      }
    } catch (const Error& e) {
      return SetText(res, 400, kErrorPrefix + std::string(e.what()));
    }
    const auto took = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start);
    res.set_header("X-Urdfsnap-Model", std::to_string(generation));
    res.set_header("X-Urdfsnap-Render-Ms", std::to_string(took.count()));
    res.set_content(std::move(png), "image/png");
  }

  // `GET /api/fit?...&link=NAME`: the orbit view (yaw, pitch, distance, focal) that frames the
  // robot, or the link NAME, as the query's options and pose show it.
  void Fit(const httplib::Request& req, httplib::Response& res) {
    const std::shared_ptr<const ModelState> state = live.State();
    if (!state->robot) return SetJson(res, 422, {{"error", kErrorPrefix + state->error}});
    Query query = req.params;
    std::string link;
    if (const auto found = query.find("link"); found != query.end()) {
      link = found->second;
      query.erase(found);
    }
    try {
      scene::OrbitView view;
      const bool ran = renderer.TryRun([&](FrameSource& frames) {
        Warnings warnings;
        view = frames.FitView(RequestFromQuery(query, options.base), link, warnings);
      });
      if (!ran) {
        res.set_header("Retry-After", "1");
        return SetJson(res, 503, {{"error", "urdfsnap serve: busy rendering; try again"}});
      }
      SetJson(res, 200, {{"yaw", view.yaw}, {"pitch", view.pitch}, {"distance", view.distance},
                         {"focal", {view.focal.x(), view.focal.y(), view.focal.z()}}});
    } catch (const Error& e) {
      SetJson(res, 400, {{"error", kErrorPrefix + std::string(e.what())}});
    }
  }

  void View(httplib::Response& res) {
    const std::lock_guard lock(initial_view_mutex);
    if (!initial_view.empty()) return res.set_content(initial_view, "application/json");
    SetJson(res, 422, {{"error", kErrorPrefix + live.State()->error}});
  }

  void Robot(httplib::Response& res) {
    const std::shared_ptr<const ModelState> state = live.State();
    if (!state->robot) {
      return SetJson(res, 422, {{"error", kErrorPrefix + state->error}, {"model", state->generation}});
    }
    res.set_content(PageRobotJson(*state->robot, state->warnings), "application/json");
  }

  void Status(httplib::Response& res) {
    const std::shared_ptr<const ModelState> state = live.State();
    nlohmann::json error = nullptr;
    if (!state->robot) error = kErrorPrefix + state->error;
    nlohmann::json recording = nullptr;
    if (options.recording) recording = {{"duration", options.recording->duration}};
    // a calibrated camera is placed as given: the page's orbit controls have nothing to move
    const std::string camera_view = CameraViewText(options.base);
    SetJson(res, 200, {{"model", state->generation}, {"error", error}, {"recording", recording},
                       {"camera", !camera_view.empty()}, {"camera_view", camera_view}});
  }

  void Route() {
    http.new_task_queue = [n = options.threads] { return new httplib::ThreadPool(n); };
    http.set_payload_max_length(4096);
    http.set_keep_alive_max_count(1000);  // each request within options.stream_limits
    http.set_tcp_nodelay(true);
    // SO_REUSEADDR only: the library's default adds SO_REUSEPORT, which would let a second server
    // share the port silently instead of failing to bind
    http.set_socket_options([](socket_t sock) {
      const int yes = 1;
      setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    const bool loopback_only = IsLoopback(options.bind);
    http.set_pre_routing_handler([this, loopback_only](const httplib::Request& req, httplib::Response& res) {
      http.RequestArrived();
      res.set_header("Cache-Control", "no-store");
      res.set_header("X-Content-Type-Options", "nosniff");
      if (loopback_only && !IsLoopback(HostName(req.get_header_value("Host")))) {
        SetText(res, 403, "urdfsnap serve answers to localhost only (it was started without --bind)");
        return httplib::Server::HandlerResponse::Handled;
      }
      return httplib::Server::HandlerResponse::Unhandled;
    });
    http.Get("/", [this](const httplib::Request&, httplib::Response& res) {
      // the page runs only its own script and style, and talks only to this server
      res.set_header("Content-Security-Policy",
                     "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' blob:; "
                     "connect-src 'self' blob:; base-uri 'none'; form-action 'none'; frame-ancestors 'none'");
      Page("index.html", "text/html; charset=utf-8", res);
    });
    http.Get("/page.js", [this](const httplib::Request&, httplib::Response& res) {
      Page("page.js", "text/javascript; charset=utf-8", res);
    });
    http.Get("/page.css", [this](const httplib::Request&, httplib::Response& res) {
      Page("page.css", "text/css; charset=utf-8", res);
    });
    http.Get("/favicon.svg", [this](const httplib::Request&, httplib::Response& res) {
      Page("favicon.svg", "image/svg+xml", res);
    });
    http.Get("/render.png", [this](const httplib::Request& req, httplib::Response& res) { RenderFrame(req, res); });
    http.Get("/api/robot", [this](const httplib::Request&, httplib::Response& res) { Robot(res); });
    http.Get("/api/status", [this](const httplib::Request&, httplib::Response& res) { Status(res); });
    http.Get("/api/view", [this](const httplib::Request&, httplib::Response& res) { View(res); });
    http.Get("/api/fit", [this](const httplib::Request& req, httplib::Response& res) { Fit(req, res); });
    http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) {
        SetText(res, res.status, "urdfsnap serve: " + std::to_string(res.status) + " " + Reason(res.status));
      }
    });
    http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
      try {
        std::rethrow_exception(error);
      } catch (const std::exception& e) {
        SetText(res, 500, kErrorPrefix + std::string(e.what()));
      } catch (...) {
        SetText(res, 500, std::string(kErrorPrefix) + "unknown failure");
      }
    });
  }
};

Server::Server(ServerOptions options, Warnings& warnings)
    : impl_(std::make_unique<Impl>(std::move(options))) {
  Impl& s = *impl_;
  CheckOptionValues(s.options.base);
  const std::shared_ptr<const ModelState> state = s.Reload(warnings);
  for (const auto& warning : state->warnings) warnings.Add(warning);
  if (!state->robot) warnings.Add(state->error + " (serving this error until the model loads)");
  s.Route();
}

Server::~Server() = default;

int Server::Bind() {
  Impl& s = *impl_;
  const std::string where = s.options.bind + ":" + std::to_string(s.options.port);
  const int port = s.options.port == 0 ? s.http.bind_to_any_port(s.options.bind)
                   : s.http.bind_to_port(s.options.bind, s.options.port) ? s.options.port
                                                                         : -1;
  if (port < 0) {
    throw Error("cannot listen on " + where + " (the port in use, or not an address of this "
                "machine; --port 0 picks a free port)");
  }
  return port;
}

void Server::Run() {
  Impl& s = *impl_;
  std::jthread watcher([&s](std::stop_token stop) { s.Watch(stop); });
  s.http.listen_after_bind();
}

bool Server::Stop() {
  if (!impl_->http.is_running()) return false;
  impl_->http.stop();
  return true;
}

}  // namespace urdfsnap::serve
