// FrameSource on request::RenderSession.
#include "serve/frame_source.h"

#include "image/png_writer.h"
#include "request/render_session.h"

namespace urdfsnap::serve {

namespace {

// Options named as on render's command line, so that errors read as render's do.
std::string CommandLineLabel(std::string_view name) { return "--" + std::string(name); }

}  // namespace

FrameSource::FrameSource(const gl::BackendChoice& backend)
    : session_(std::make_unique<request::RenderSession>(backend)) {}
FrameSource::~FrameSource() = default;

std::string FrameSource::RenderPng(const request::RenderRequest& request, Warnings& warnings) {
  const image::Frame frame = session_->Render(request, CommandLineLabel, warnings);
  const std::vector<std::uint8_t> png = image::EncodePng(frame.colour);
  return {png.begin(), png.end()};
}

WatchedModel FrameSource::Reload(const request::RenderRequest& request) {
  session_->ForgetModels();
  Warnings warnings;
  WatchedModel watched;
  watched.robot = session_->LoadRobot(request.model, warnings);
  session_->Render(request, CommandLineLabel, warnings);
  watched.warnings = warnings.messages();
  watched.files = session_->Files(request.model);
  return watched;
}

render::RenderSettings FrameSource::ResolvedSettings(const request::RenderRequest& request,
                                                     Warnings& warnings) {
  return session_->ResolveSettings(request, CommandLineLabel, warnings);
}

}  // namespace urdfsnap::serve
