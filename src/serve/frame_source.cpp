// FrameSource on request::RenderSession: the base's files read at each Reload, queries resolved
// over them.
#include "serve/frame_source.h"

#include <algorithm>

#include "common/error.h"
#include "image/png_writer.h"
#include "request/render_session.h"
#include "scene/view_fitting.h"
#include "serve/server.h"

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

std::string FrameSource::RenderMomentPng(const RecordingView& recording, const request::RenderRequest& request,
                                         double at, Warnings& warnings) {
  const RecordedMoment moment = recording.moment(request, at, warnings);
  const render::RenderSettings& s = moment.settings;
  gl::SceneRenderer& gl = session_->GlRenderer(s.samples);
  const image::Frame frame = s.camera && moment.robot
                                 ? moment.robot->Render(gl, moment.scene, moment.X_SF, moment.positions, *s.camera, {})
                                 : gl.Render(moment.scene, s.view, s.size.width, s.size.height);
  const std::vector<std::uint8_t> png = image::EncodePng(frame.colour);
  return {png.begin(), png.end()};
}

scene::OrbitView FrameSource::FitView(const request::RenderRequest& request, const std::string& link,
                                      Warnings& warnings) {
  request::RenderRequest fitted = request;
  fitted.fit = link.empty();   // the whole robot: the view `render --fit` draws without --focal
  fitted.focal.clear();
  const request::Prepared prepared =
      session_->Prepare(request::ResolveRequest(fitted, base_files_, request::CommandLineLabel), warnings);
  if (prepared.settings.camera) throw Error("a calibrated camera's view cannot be fitted (--camera-info)");
  if (link.empty()) return prepared.settings.view;
  const model::Robot& robot = *prepared.robot;
  const int index = robot.FindLink(link);
  if (index < 0) throw Error("link '" + link + "' is not a link of robot '" + robot.name() + "'");
  const scene::Scene posed = prepared.renderer->Pose(prepared.positions);
  // the link's geometry; for a link without any, its subtree's; for a frame with none below it
  // either (a tool point), the subtree of the nearest link above it that has some
  std::vector<bool> framed(robot.links().size(), false);
  framed[index] = true;
  const auto framed_items = [&] {
    scene::Scene scene = posed;
    std::erase_if(scene.items, [&](const scene::DrawItem& item) { return item.link < 0 || !framed[item.link]; });
    return scene;
  };
  scene::Scene scene = framed_items();
  for (int top = index; scene.items.empty();) {
    std::fill(framed.begin(), framed.end(), false);
    framed[top] = true;
    for (size_t i = 0; i < robot.links().size(); ++i) {   // parents come before their children
      const int joint = robot.links()[i].parent_joint;
      if (joint >= 0 && framed[robot.joints()[joint].parent_link]) framed[i] = true;
    }
    scene = framed_items();
    const int joint = robot.links()[top].parent_joint;
    if (joint < 0) break;
    top = robot.joints()[joint].parent_link;
  }
  if (scene.items.empty()) throw Error("robot '" + robot.name() + "' has no geometry shown to frame");
  const render::ImageSize size = prepared.settings.size;
  return scene::FitView(scene, prepared.settings.view, static_cast<double>(size.width) / size.height, false,
                        prepared.settings.fit_margin.For(size));
}

StartingView FrameSource::Start(Warnings& warnings) {
  const request::ResolvedRequest resolved = request::ResolveRequest(base_, base_files_, request::CommandLineLabel);
  return {session_->Prepare(resolved, warnings).settings, resolved.joints};
}

}  // namespace urdfsnap::serve
