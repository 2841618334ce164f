// RenderPageImages: RobotRenderers for the views (visual, collision, TF) and one faded variant per
// joint section, all drawn by one gl::SceneRenderer; stills as PNG, animations through
// animation_output.
#include "docs/page_images.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>

#include "docs/animation_output.h"
#include "docs/repeated_scenes.h"
#include "gl/scene_renderer.h"
#include "image/png_writer.h"
#include "model/joint_values.h"
#include "render/robot_renderer.h"
#include "render/turntable_fit.h"
#include "scene/view_fitting.h"

namespace urdfsnap::docs {

namespace {

render::ImageSize SizeOf(PictureSize size) { return {size.width, size.height}; }

// The length of RViz's TF axes at marker scale 1 (tf_display.cpp), in metres.
constexpr double kRvizAxisLength = 0.2;

// The page's TF picture before it is drawn.
struct TfPicture {
  scene::Scene scene;
  scene::OrbitView view;
  render::ImageSize size;
  std::vector<LeftOutName> left_out;   // the frames whose names it leaves out
};

// The TF frames of the robot as shown (`visual`) from the camera that frames it, their axes a
// share of the picture's height (unless --tf-scale was given) and their names laid out so that
// none hides another. GL-free.
TfPicture LayOutTfPicture(const std::shared_ptr<const model::Robot>& robot, const render::RobotRenderer& visual,
                          const RobotPage& page, const PageLook& look, Warnings& warnings) {
  TfPicture tf;
  tf.size = SizeOf(page.tf_size);
  const auto pose = [&](int) { return page.default_positions; };
  tf.view = visual.FitView(look.settings.fit, look.settings.fit_margin, look.settings.view, tf.size, 1, pose);
  scene::SceneOptions options = look.settings.scene;
  options.tf.enabled = true;
  options.alpha *= look.tf_alpha;
  if (!look.tf_scale_given) {
    const double picture_height = 2 * tf.view.distance * std::tan(tf.view.fov_y / 2);   // metres at the focal point
    options.tf.marker_scale = look.tf_axis_share * picture_height / kRvizAxisLength;
  }
  const render::RobotRenderer frames(robot, options, warnings);
  tf.scene = frames.Pose(page.default_positions);
  if (!tf.scene.labels.empty()) tf.left_out = LayOutTfNames(tf.scene, robot->LinkNames(), tf.view, tf.size);
  return tf;
}

class PageRenderer {
 public:
  PageRenderer(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page, const PageLook& look,
               const std::filesystem::path& folder, Warnings& warnings, const Progress& progress)
      : robot_(robot), page_(page), look_(look), folder_(folder), warnings_(warnings), progress_(progress),
        gl_(look.settings.samples, look.backend), visual_(robot, look.settings.scene, warnings) {}

  // Makes `files` of the page, in page order; the progress counts on from the files made before.
  void Make(const std::vector<PageImage>& files) {
    wanted_.clear();
    for (const PageImage& file : files) wanted_.insert(file.file);
    total_ += ImageCount(files);
    Views();
    for (const JointSection& section : page_.sections) Section(section);
  }

  // The frame names the TF picture leaves out.
  const std::vector<LeftOutName>& tf_left_out() {
    if (!tf_left_out_) tf_left_out_ = TfView();
    return *tf_left_out_;
  }

 private:
  void Views() {
    scene::SceneOptions options = look_.settings.scene;
    if (Wanted(page_.hero_file)) Still(visual_, page_.hero_file);

    if (Wanted(page_.collision_file)) {
      options.show_visual = false;
      options.show_collision = true;
      Still(render::RobotRenderer(robot_, options, warnings_), page_.collision_file);
    }

    if (Wanted(page_.tf_file)) tf_left_out_ = TfView();

    if (Wanted(page_.turntable_file)) Turntable(visual_);
  }

  void Section(const JointSection& section) {
    const bool any = Wanted(section.sweep_file) ||
                     std::any_of(section.pictures.begin(), section.pictures.end(),
                                 [&](const Picture& picture) { return Wanted(picture.file); });
    if (!any) return;
    // the links the joint does not move, faded
    scene::SceneOptions options = look_.settings.scene;
    std::vector<bool> moving(robot_->links().size(), false);
    for (int link : section.moving_links) moving[link] = true;
    for (size_t i = 0; i < moving.size(); ++i) {
      if (!moving[i]) options.link_alpha[robot_->links()[i].name] = look_.faded_alpha;
    }
    const render::RobotRenderer faded(robot_, options, warnings_);
    // one camera for the stills and every frame of the sweep, fitted to what moves
    const int stills = static_cast<int>(section.pictures.size());
    model::NamedValues others = PagePoseWithout(section.joint);
    const auto pose = [&](int k) {
      others.emplace_back(section.name, k < stills ? section.pictures[k].position : section.sweep[k - stills]);
      std::vector<double> positions = model::ResolveJointPositions(*robot_, others, false, ignored_);
      others.pop_back();
      return positions;
    };
    const int count = stills + static_cast<int>(section.sweep.size());
    const scene::OrbitView view = MotionView(faded, moving, count, pose);
    // each distinct picture drawn once: a joint moving only links without geometry shows one
    // scene in every still and sweep frame (the PR2's gripper motor screws)
    RepeatedScenes repeated(count, [&](int k) { return faded.Pose(pose(k)); });
    const auto picture = [&](int k) {
      return repeated.Picture(k, [&] { return faded.Render(gl_, pose(k), view, SizeOf(page_.joint_size)).colour; });
    };
    for (int k = 0; k < stills; ++k) {
      if (Wanted(section.pictures[k].file)) Write(picture(k), section.pictures[k].file);
    }
    if (Wanted(section.sweep_file)) {
      WriteFrames(section.sweep_file, static_cast<int>(section.sweep.size()), [&](int k) { return picture(stills + k); });
    }
  }

  // Whether `file` is one to make here (never "": a picture the page does not have).
  bool Wanted(const std::string& file) const { return wanted_.count(file) > 0; }

  // The view that fits the moving links in every pose(k), k < count (the whole robot when they have
  // no geometry), so that a small part fills the picture.
  scene::OrbitView MotionView(const render::RobotRenderer& robot, const std::vector<bool>& moving, int count,
                              const std::function<std::vector<double>(int)>& pose) {
    const auto moving_parts = [&](int k) {
      scene::Scene scene = robot.Pose(pose(k));
      std::erase_if(scene.items, [&](const scene::DrawItem& item) { return item.link < 0 || !moving[item.link]; });
      return scene;
    };
    const render::Fit fit = look_.settings.fit;
    if (moving_parts(0).items.empty()) return robot.FitView(fit, look_.settings.fit_margin, look_.settings.view, SizeOf(page_.joint_size), count, pose);
    const double aspect = static_cast<double>(page_.joint_size.width) / page_.joint_size.height;
    return scene::FitView(count, moving_parts, look_.settings.view, aspect, fit == render::Fit::kKeepFocal,
                          look_.settings.fit_margin.For(SizeOf(page_.joint_size)));
  }

  // The page's pose as values of the joints a value moves, but `joint`: with its value added, what
  // ResolveJointPositions makes of them is the page's pose with that joint moved (its mimics
  // following).
  model::NamedValues PagePoseWithout(int joint) const {
    model::NamedValues values;
    const auto& joints = robot_->joints();
    for (size_t j = 0; j < joints.size(); ++j) {
      if (static_cast<int>(j) != joint && joints[j].IsMovable() && joints[j].mimic_leader < 0) {
        values.emplace_back(joints[j].name, page_.default_positions[j]);
      }
    }
    return values;
  }

  void Still(const render::RobotRenderer& robot, const std::string& file) {
    const auto pose = [&](int) { return page_.default_positions; };
    const render::ImageSize size = SizeOf(page_.view_size);
    const scene::OrbitView view = robot.FitView(look_.settings.fit, look_.settings.fit_margin, look_.settings.view, size, 1, pose);
    Write(robot.Render(gl_, page_.default_positions, view, size).colour, file);
  }

  // The TF picture, drawn when wanted; laid out always: the page names what it leaves out.
  // Returns those names.
  std::vector<LeftOutName> TfView() {
    TfPicture tf = LayOutTfPicture(robot_, visual_, page_, look_, warnings_);
    if (Wanted(page_.tf_file)) Write(gl_.Render(tf.scene, tf.view, tf.size.width, tf.size.height).colour, page_.tf_file);
    return tf.left_out;
  }

  // The camera's yaw once around, at the distance that frames the robot from every side.
  void Turntable(const render::RobotRenderer& robot) {
    const int frames = look_.turntable_frames;
    const render::ImageSize size = SizeOf(page_.joint_size);
    const auto pose = [&](int) { return page_.default_positions; };
    const auto yaw = [&](int k) { return look_.settings.view.yaw + 2 * std::numbers::pi * k / frames; };
    const scene::OrbitView fitted =
        render::FitTurntable(robot, look_.settings.fit, look_.settings.fit_margin, look_.settings.view, size, frames, pose, yaw);
    Animate(robot, page_.turntable_file, frames, pose, [&](int k) {
      scene::OrbitView view = fitted;
      view.yaw = yaw(k);
      return view;
    });
  }

  // Writes the animation of `frames` frames, frame k showing pose(k) through view(k).
  void Animate(const render::RobotRenderer& robot, const std::string& file, int frames,
               const std::function<std::vector<double>(int)>& pose,
               const std::function<scene::OrbitView(int)>& view) {
    WriteFrames(file, frames, [&](int k) { return robot.Render(gl_, pose(k), view(k), SizeOf(page_.joint_size)).colour; });
  }

  // Writes the animation of `frames` frames, frame k being frame(k).
  void WriteFrames(const std::string& file, int frames, const std::function<image::Image(int)>& frame) {
    const std::filesystem::path path = folder_ / file;
    std::filesystem::create_directories(path.parent_path());
    WriteAnimation(path.string(), page_.joint_size, look_.fps, frames, [&](int k, image::Image& image) {
      image = frame(k);
      Advance();
    });
  }

  // A picture as PNG, or as WebP (lossy) through the animation encoder: a one-frame animation.
  void Write(const image::Image& image, const std::string& file) {
    const std::filesystem::path path = folder_ / file;
    std::filesystem::create_directories(path.parent_path());
    if (path.extension() == ".png") {
      image::WritePng(image, path.string());
    } else {
      WriteAnimation(path.string(), {image.width, image.height}, look_.fps, 1,
                     [&](int, image::Image& frame) { frame = image; });
    }
    Advance();
  }

  void Advance() {
    if (progress_) progress_(++done_, total_);
  }

  std::shared_ptr<const model::Robot> robot_;
  const RobotPage& page_;
  const PageLook& look_;
  const std::filesystem::path folder_;
  Warnings& warnings_;
  Warnings ignored_;   // a section's poses': the page's pose was warned of when it was resolved
  const Progress& progress_;
  std::int64_t total_ = 0;
  std::int64_t done_ = 0;
  gl::SceneRenderer gl_;
  // the robot as shown, kept for the whole page: while it holds the mesh files and textures, every
  // faded variant gets the same ones from their caches and gl_ keeps them uploaded (dropped with
  // each variant, the PR2's were decoded and uploaded again for each of its 39 joint sections)
  const render::RobotRenderer visual_;
  std::set<std::string> wanted_;
  std::optional<std::vector<LeftOutName>> tf_left_out_;   // laid out with the TF picture, or when asked
};

}  // namespace

std::vector<PageImage> PageImages(const RobotPage& page, const PageLook& look) {
  std::vector<PageImage> files = {{page.hero_file, 1, 0}};
  if (!page.collision_file.empty()) files.push_back({page.collision_file, 1, 1});
  files.push_back({page.tf_file, 1, 2});
  if (!page.turntable_file.empty()) files.push_back({page.turntable_file, look.turntable_frames, 3});
  int group = 4;
  for (const JointSection& section : page.sections) {
    for (const Picture& picture : section.pictures) files.push_back({picture.file, 1, group});
    if (!section.sweep_file.empty()) {
      files.push_back({section.sweep_file, static_cast<std::int64_t>(section.sweep.size()), group});
    }
    ++group;
  }
  return files;
}

std::int64_t ImageCount(const std::vector<PageImage>& files) {
  std::int64_t count = 0;
  for (const PageImage& file : files) count += file.images;
  return count;
}

std::vector<LeftOutName> TfLeftOut(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page,
                                   const PageLook& look, Warnings& warnings) {
  return LayOutTfPicture(robot, render::RobotRenderer(robot, look.settings.scene, warnings), page, look, warnings).left_out;
}

std::vector<LeftOutName> RenderPageImages(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page,
                                          const PageLook& look, const std::vector<PageImage>& files,
                                          const std::filesystem::path& folder, Warnings& warnings,
                                          const Progress& progress) {
  PageRenderer renderer(robot, page, look, folder, warnings, progress);
  renderer.Make(files);
  return renderer.tf_left_out();
}

void RenderPagePieces(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page, const PageLook& look,
                      const std::function<std::optional<std::vector<PageImage>>()>& next,
                      const std::filesystem::path& folder, Warnings& warnings, const Progress& progress) {
  PageRenderer renderer(robot, page, look, folder, warnings, progress);
  while (const std::optional<std::vector<PageImage>> files = next()) renderer.Make(*files);
}

}  // namespace urdfsnap::docs
