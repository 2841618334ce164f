// RenderSession: requests prepared (models and prepared robots cached, most recently used first,
// bounded; joint values resolved; the view fitted) and frames drawn from them.
#include "request/render_session.h"

#include <algorithm>
#include <utility>

#include "common/error.h"
#include "model/forward_kinematics.h"
#include "model/joint_values.h"

namespace urdfsnap::request {

namespace {

void AddAll(const Warnings& from, Warnings& to) {
  for (const auto& message : from.messages()) to.Add(message);
}

// Moves the first entry of `entries` that `matches` to the front and returns it; null if none.
template <typename Entry, typename Matches>
Entry* MoveToFront(std::list<Entry>& entries, Matches matches) {
  const auto it = std::find_if(entries.begin(), entries.end(), matches);
  if (it == entries.end()) return nullptr;
  entries.splice(entries.begin(), entries, it);
  return &entries.front();
}

// Puts `entry` first and drops the least recently used entries beyond `capacity`.
template <typename Entry>
Entry& PushFront(std::list<Entry>& entries, Entry entry, size_t capacity) {
  entries.push_front(std::move(entry));
  while (entries.size() > capacity) entries.pop_back();
  return entries.front();
}

}  // namespace

RenderSession::RenderSession(gl::BackendChoice backend) : backend_(std::move(backend)) {}
RenderSession::~RenderSession() = default;

const RenderSession::Model& RenderSession::LoadedModelFor(const ModelRequest& request) {
  if (Model* found = MoveToFront(models_, [&](const Model& m) { return m.request == request; })) return *found;
  Model model{request, {}, {}};
  model.loaded = LoadModel(request, model.warnings);
  // robots prepared from an older load of this model must not outlive it
  robots_.remove_if([&](const Robot& r) { return r.model == request; });
  return PushFront(models_, std::move(model), kCachedModels);
}

const RenderSession::Robot& RenderSession::RobotFor(const ModelRequest& request, const Model& model,
                                                    const scene::SceneOptions& options) {
  if (Robot* found = MoveToFront(robots_, [&](const Robot& r) {
        return r.model == request && r.options == options;
      })) {
    return *found;
  }
  Robot robot{request, options, nullptr, {}};
  robot.renderer = std::make_unique<render::RobotRenderer>(model.loaded.robot, options, robot.warnings);
  return PushFront(robots_, std::move(robot), kCachedRobots);
}

gl::SceneRenderer& RenderSession::GlRenderer(int samples) { return GlRenderer(samples, backend_.backend); }

gl::SceneRenderer& RenderSession::GlRenderer(int samples, std::optional<gl::Backend> backend) {
  std::unique_ptr<gl::SceneRenderer>& renderer = renderers_[{samples, backend}];
  if (!renderer) {
    gl::BackendChoice choice = backend_;   // who asked, and whom to tell of a new context
    choice.backend = backend;
    renderer = std::make_unique<gl::SceneRenderer>(samples, std::move(choice));
  }
  return *renderer;
}

std::shared_ptr<const model::Robot> RenderSession::LoadRobot(const ModelRequest& request, Warnings& warnings) {
  const Model& model = LoadedModelFor(request);
  AddAll(model.warnings, warnings);
  return model.loaded.robot;
}

const render::RobotRenderer& RenderSession::PreparedRobot(const ModelRequest& request,
                                                          const scene::SceneOptions& options, Warnings& warnings) {
  const Robot& prepared = RobotFor(request, LoadedModelFor(request), options);
  AddAll(prepared.warnings, warnings);
  return *prepared.renderer;
}

namespace {

// The view's Target Frame (--follow, an .rviz view's): the focal point relative to that link's
// origin in this pose. A frame the robot lacks is an error given on the command line, and from
// an .rviz file a warning (RViz would look it up in TF, which a still without a bag has not).
void FollowTargetFrame(const ResolvedRequest& r, const render::RobotRenderer& renderer,
                       const std::vector<double>& positions, render::RenderSettings& settings, Warnings& warnings) {
  if (settings.target_frame.empty()) return;
  const model::Robot& robot = renderer.robot();
  const int link = robot.FindLink(settings.target_frame);
  if (link < 0) {
    const std::string problem = "'" + settings.target_frame + "' is not a link of robot '" + robot.name() + "'";
    if (r.target_frame_given) throw Error("--follow " + problem + " (frames outside it are followed with --bag)");
    warnings.Add(r.rviz + ": the view's Target Frame " + problem + "; the view orbits in the fixed frame");
    return;
  }
  settings.view.focal += renderer.scene().LinkPoses(model::ComputeLinkPoses(robot, positions))[link].translation();
}

}  // namespace

Prepared RenderSession::Prepare(const ResolvedRequest& r, Warnings& warnings) {
  const std::shared_ptr<const model::Robot> loaded = LoadRobot(r.model, warnings);
  const model::Robot& robot = *loaded;
  render::RenderSettings settings = r.settings;
  // .rviz files often name a frame outside the robot (map, odom); RViz would show nothing useful
  if (!r.fixed_frame_given && !settings.scene.fixed_frame.empty() &&
      robot.FindLink(settings.scene.fixed_frame) < 0) {
    warnings.Add(r.rviz + ": Fixed Frame '" + settings.scene.fixed_frame +
                 "' is not a link of the robot; using the root link '" + robot.links()[0].name + "'");
    settings.scene.fixed_frame.clear();
  }
  std::vector<double> positions = model::ResolveJointPositions(robot, r.joints, r.clamp, warnings);
  const render::RobotRenderer& renderer = PreparedRobot(r.model, settings.scene, warnings);
  FollowTargetFrame(r, renderer, positions, settings, warnings);
  settings.view = renderer.FitView(settings.fit, settings.fit_margin, settings.view, settings.size, 1,
                                   [&](int) { return positions; });
  settings.fit = render::Fit::kNone;
  return {loaded, std::move(settings), std::move(positions), &renderer};
}

Prepared RenderSession::Prepare(const RenderRequest& r, const OptionLabel& label, Warnings& warnings) {
  return Prepare(ResolveRequest(r, label, warnings), warnings);
}

image::Frame RenderSession::Draw(const Prepared& p, const image::FrameOutputs& outputs) {
  return p.renderer->Render(GlRenderer(p.settings.samples), p.positions, p.settings, outputs);
}

Rendered RenderSession::Render(const RenderRequest& r, const OptionLabel& label, Warnings& warnings,
                               const image::FrameOutputs& outputs) {
  const Prepared p = Prepare(r, label, warnings);
  return {Draw(p, outputs), p.robot};
}

std::vector<std::string> RenderSession::Files(const ModelRequest& request) const {
  std::vector<std::string> files;
  const auto add = [&](const std::string& file) {
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  };
  for (const Model& model : models_) {
    if (model.request == request) std::for_each(model.loaded.files.begin(), model.loaded.files.end(), add);
  }
  for (const Robot& robot : robots_) {
    if (robot.model == request) {
      const auto& used = robot.renderer->scene().files();
      std::for_each(used.begin(), used.end(), add);
    }
  }
  return files;
}

void RenderSession::ForgetModels() {
  robots_.clear();
  models_.clear();
}

}  // namespace urdfsnap::request
