// The robot's scene, the displays' items on top, one GL render.
#include "request/display_frame.h"

#include "geometry/mesh_uri.h"
#include "model/forward_kinematics.h"

namespace urdfsnap::request {

display::MarkerResources MarkerResourcesFor(const scene::SceneOptions& options) {
  return {[model_file = options.model_file, packages = options.packages](const std::string& uri) {
    return geometry::LoadMeshFile(geometry::ResolveMeshUri(uri, model_file, packages));
  }};
}

display::FrameLookup RobotFrames(const model::Robot& robot, const std::vector<Eigen::Isometry3d>& X_RL,
                                 int fixed_link) {
  return [&robot, &X_RL, fixed_link](const std::string& frame, std::int64_t) -> std::optional<Eigen::Isometry3d> {
    const int link = robot.FindLink(frame);
    if (link < 0) return std::nullopt;
    return X_RL[fixed_link].inverse() * X_RL[link];
  };
}

image::Frame DrawWithDisplays(RenderSession& session, const Prepared& prepared,
                              const display::DisplaySet& displays, Warnings& warnings,
                              const image::FrameOutputs& outputs) {
  const render::RenderSettings& s = prepared.settings;
  const std::vector<Eigen::Isometry3d> X_RL = model::ComputeLinkPoses(*prepared.robot, prepared.positions);
  const scene::RobotScene& robot_scene = prepared.renderer->scene();
  scene::Scene scene = robot_scene.Pose(X_RL);
  displays.Draw(0, RobotFrames(*prepared.robot, X_RL, robot_scene.fixed_link()), scene, warnings);
  gl::SceneRenderer& gl = session.GlRenderer(s.samples);
  if (s.camera) return prepared.renderer->Render(gl, scene, Eigen::Isometry3d::Identity(), prepared.positions, *s.camera, outputs);
  return gl.Render(scene, s.view, s.size.width, s.size.height, outputs);
}

}  // namespace urdfsnap::request
