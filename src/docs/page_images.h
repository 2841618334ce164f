// Rendering a docs page's pictures and animations through the typed render core, in one process
// with one GL context: the robot as RViz shows it (framed with --fit), its collision geometry, its
// TF frames with names, a turntable, and per joint section the stills and the sweep from one
// camera fitted to the links the joint moves through its whole motion, with the links it does not
// move faded (each faded variant prepared once).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/warnings.h"
#include "docs/page_model.h"
#include "docs/tf_name_layout.h"
#include "gl/backend.h"
#include "model/robot.h"
#include "render/render_settings.h"

namespace urdfsnap::docs {

// How the pictures look beyond the page's content.
struct PageLook {
  // The user's displays, camera direction, multisampling and fit (`urdfsnap docs` always fits:
  // Fit::kKeepFocal when a focal point was given, else Fit::kFit); size is page.view_size.
  render::RenderSettings settings;
  double faded_alpha = 0.25;   // link alpha of the links a joint does not move
  double tf_alpha = 0.3;       // multiplies the robot's alpha in the TF view, so frames inside show
  double tf_axis_share = 0.05; // TF axes' length in the TF view, a share of the picture's height
  bool tf_scale_given = false; // --tf-scale sizes the TF view's axes instead
  int turntable_frames = 36;   // one turn of the camera's yaw (3.6 s)
  double fps = 10;             // of every animation: whole centiseconds, as GIF holds them
  gl::BackendChoice backend;   // the GL backend that draws them ({}: URDFSNAP_GL_BACKEND, else auto)
};

// Called after each picture or animation frame: how many are done of how many in all.
using Progress = std::function<void(std::int64_t done, std::int64_t total)>;

// A picture or an animation of the page: its file, relative to the page, and the images it takes
// to make (1 for a picture, its frames for an animation).
struct PageImage {
  std::string file;
  std::int64_t images = 1;
  int group = 0;   // PageImages: a joint section's files share one (their camera is fitted once), each view has its own
};

// Every picture and animation of `page`, in the order RenderPageImages makes them: the robot, its
// collision geometry, TF frames, turntable, then each joint section's pictures and sweep.
std::vector<PageImage> PageImages(const RobotPage& page, const PageLook& look);

// The pictures and animation frames of `files` together: the progress total of making them.
std::int64_t ImageCount(const std::vector<PageImage>& files);

// Renders the pictures and animations of `page` (made by MakeRobotPage for `robot`) that `files`
// lists (PageImages, or a shard's part of them) into `folder`, at the page's relative file names;
// each camera is fitted as for the whole page, so a picture is the same whichever part it is made
// in. Pictures are PNG or WebP by their extension. Returns the frame names the TF picture leaves
// out (the same whichever part is made). Throws urdfsnap::Error: files the robot needs that cannot
// be read (located at the link), no GL context, an image that cannot be written.
std::vector<LeftOutName> RenderPageImages(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page,
                      const PageLook& look, const std::vector<PageImage>& files,
                      const std::filesystem::path& folder, Warnings& warnings, const Progress& progress);

// Renders the pictures and animations of `page` piece by piece, as RenderPageImages does, in one GL
// context (meshes and textures uploaded once): the files of each piece `next()` gives, until it
// gives none (nullopt). For the worker processes of `docs --jobs`, which take pieces as they
// finish others. The progress counts every image made so far.
void RenderPagePieces(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page, const PageLook& look,
                      const std::function<std::optional<std::vector<PageImage>>()>& next,
                      const std::filesystem::path& folder, Warnings& warnings, const Progress& progress);

// The frame names the TF picture of `page` leaves out, as RenderPageImages returns them, without
// drawing anything (GL-free): for the page's text when its pictures are made elsewhere (docs
// --jobs). Throws urdfsnap::Error as RenderPageImages does for files the robot needs.
std::vector<LeftOutName> TfLeftOut(const std::shared_ptr<const model::Robot>& robot, const RobotPage& page,
                                   const PageLook& look, Warnings& warnings);

}  // namespace urdfsnap::docs
