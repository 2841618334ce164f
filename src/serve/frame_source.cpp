// FrameSource on request::RenderSession.
#include "serve/frame_source.h"

#include "image/png_writer.h"
#include "model/joint_values.h"
#include "render/robot_renderer.h"
#include "request/render_session.h"
#include "request/settings_parsing.h"

namespace urdfsnap::serve {

namespace {

// Options named as on render's command line, so that errors read as render's do.
std::string CommandLineLabel(std::string_view name) { return "--" + std::string(name); }

}  // namespace

FrameSource::FrameSource() : session_(std::make_unique<request::RenderSession>()) {}
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
  render::RenderSettings settings = request::ParseRenderSettings(request, CommandLineLabel, warnings);
  if (settings.fit == render::Fit::kNone) return settings;
  // the fitted view as RenderSession::Render frames it (until the session reports the view it
  // rendered with, this repeats its steps: the pose, the prepared robot, FitView)
  const std::shared_ptr<const model::Robot> robot = session_->LoadRobot(request.model, warnings);
  model::NamedValues given;
  if (!request.joint_file.empty()) given = model::ReadJointFile(request.joint_file);
  given.insert(given.end(), request.joints.begin(), request.joints.end());
  const std::vector<double> positions =
      model::ResolveJointPositions(*robot, given, !request.no_clamp, warnings);
  if (request.fixed_frame.empty() && robot->FindLink(settings.scene.fixed_frame) < 0) {
    settings.scene.fixed_frame.clear();  // an .rviz file's frame outside the robot: the root
  }
  const render::RobotRenderer renderer(robot, settings.scene, warnings);
  settings.view = renderer.FitView(settings.fit, settings.view, settings.size, 1,
                                   [&](int) { return positions; });
  settings.fit = render::Fit::kNone;
  return settings;
}

}  // namespace urdfsnap::serve
