// FrameSource on request::RenderSession: the base's files read at each Reload, queries resolved
// over them.
#include "serve/frame_source.h"

#include "image/png_writer.h"
#include "request/render_session.h"

namespace urdfsnap::serve {

FrameSource::FrameSource(const gl::BackendChoice& backend)
    : session_(std::make_unique<request::RenderSession>(backend)) {}
FrameSource::~FrameSource() = default;

WatchedModel FrameSource::Reload(const request::RenderRequest& base) {
  session_->ForgetModels();
  Warnings warnings;
  WatchedModel watched;
  base_files_ = request::ReadRequestFiles(base, warnings);
  base_ = base;
  const request::Prepared prepared =
      session_->Prepare(request::ResolveRequest(base, base_files_, request::CommandLineLabel), warnings);
  session_->Draw(prepared);
  watched.robot = prepared.robot;
  watched.warnings = warnings.messages();
  watched.files = session_->Files(base.model);
  for (const std::string* file : {&base.rviz, &base.joint_file, &base.camera_info, &base.underlay}) {
    if (!file->empty()) watched.files.push_back(*file);
  }
  return watched;
}

std::string FrameSource::RenderPng(const request::RenderRequest& request, Warnings& warnings) {
  const request::Prepared prepared =
      session_->Prepare(request::ResolveRequest(request, base_files_, request::CommandLineLabel), warnings);
  const std::vector<std::uint8_t> png = image::EncodePng(session_->Draw(prepared).colour);
  return {png.begin(), png.end()};
}

StartingView FrameSource::Start(Warnings& warnings) {
  const request::ResolvedRequest resolved = request::ResolveRequest(base_, base_files_, request::CommandLineLabel);
  return {session_->Prepare(resolved, warnings).settings, resolved.joints};
}

}  // namespace urdfsnap::serve
