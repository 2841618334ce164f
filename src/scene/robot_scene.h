// A robot as RViz's RobotModel, Grid and TF displays show it, decided once and placed per frame:
// RobotScene resolves mesh and texture URIs, loads the files (in parallel), applies RViz's material
// rules and lays out the TF names when it is made; Pose() then only places the parts for one set
// of link poses (no file I/O, no resolving), as Drake registers geometry once and updates poses.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/warnings.h"
#include "model/robot.h"
#include "scene/scene.h"
#include "scene/scene_options.h"

namespace urdfsnap::scene {

// One drawn mesh of a visual or collision shape, in its link's frame.
struct LinkPart {
  int link = -1;                          // index into robot.links()
  std::shared_ptr<const geometry::TriangleMesh> mesh;
  Eigen::Affine3d X_LG = Eigen::Affine3d::Identity();   // in the link frame, scale included
  Eigen::Vector4f rgba{1, 0, 0, 1};       // RobotModel alpha and the link's alpha applied
  std::shared_ptr<const texture::TextureImage> texture;
  int texture_units = 1;                  // how often `texture` modulates (scene::DrawItem)
  Eigen::Vector3f emissive{0, 0, 0};
};

class RobotScene {
 public:
  // Prepares `robot` (which must outlive this object) for `options`: every mesh and texture the
  // shown displays need is found and loaded. Throws urdfsnap::Error located at the link's element
  // for a mesh or texture that cannot be found or read (with allow_missing_meshes, a missing one
  // is a warning and is not drawn), for an unknown fixed frame, a link alpha for an unknown link
  // or outside 0 to 1, and when TF names are asked for and the font is missing.
  RobotScene(const model::Robot& robot, SceneOptions options, Warnings& warnings);

  const model::Robot& robot() const { return robot_; }
  const SceneOptions& options() const { return options_; }
  const std::vector<LinkPart>& parts() const { return parts_; }
  // The triangles of all parts: what each frame draws of the robot.
  std::size_t triangle_count() const;
  // The index of the fixed frame's link in robot.links() (0, the root, when none is named).
  int fixed_link() const { return fixed_link_; }
  // The mesh and texture files read, resolved and without repeats, in the order first used.
  const std::vector<std::string>& files() const { return files_; }

  // The scene for link poses X_RL (one per robot.links(), in the root frame R, as
  // model::ComputeLinkPoses returns them), in the fixed frame: draw items with their link index,
  // TF markers, grid, background. X_SF places the fixed link in the scene's frame: the identity,
  // or, for a fixed frame outside the robot (odom, map from a bag's TF, as RViz's Fixed Frame), the
  // pose TF gives the fixed link there. Does no I/O.
  Scene Pose(const std::vector<Eigen::Isometry3d>& X_RL,
             const Eigen::Isometry3d& X_SF = Eigen::Isometry3d::Identity()) const;
  // The link poses in the scene's frame that Pose draws them at.
  std::vector<Eigen::Isometry3d> LinkPoses(const std::vector<Eigen::Isometry3d>& X_RL,
                                           const Eigen::Isometry3d& X_SF = Eigen::Isometry3d::Identity()) const;

 private:
  const model::Robot& robot_;
  SceneOptions options_;
  int fixed_link_ = 0;
  std::vector<LinkPart> parts_;
  std::vector<TextLabel> tf_names_;   // anchored at the origin; Pose() moves them to the frames
  std::vector<int> tf_parents_;       // robot.ParentLinks(), for the TF display
  std::vector<std::string> files_;
};

}  // namespace urdfsnap::scene
