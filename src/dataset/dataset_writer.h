// `urdfsnap dataset`: N samples of a robot in random poses seen by a camera placed at random on a
// sphere around it (or at poses given), written as colour, depth and label images and one COCO annotation file. Each
// sample depends only on (seed, its index), so runs, shards and reruns agree byte for byte.
//
//   DIR/images/000000.png   colour (8-bit RGB)
//   DIR/depth/000000.png    depth, 16-bit millimetres along the optical axis, 0 off the robot
//   DIR/labels/000000.png   16-bit, 1 + link index, 0 off the robot
//   DIR/annotations.json    COCO (DIR/annotations.K-of-N.json for shard K of N)
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/atomic_file.h"
#include "common/warnings.h"
#include "dataset/sampling.h"
#include "gl/scene_renderer.h"
#include "render/robot_renderer.h"
#include "shard/shard_assignment.h"

namespace urdfsnap::dataset {

struct DatasetSpec {
  std::string folder;
  std::int64_t count = 0;            // samples in the whole dataset
  std::uint64_t seed = 0;
  Interval distance;                 // m from the robot's centre
  Interval elevation{0, 60};         // degrees above the horizontal plane
  // when not empty, sample k is seen from camera_poses[k % size] in the camera's frame (its link,
  // or the root link) instead of from a random place on the sphere
  std::vector<Eigen::Isometry3d> camera_poses;
  shard::FrameRange range;           // the samples this run writes
  std::string annotations_file;      // the COCO file's name in `folder`
};

// Writes the samples spec.range of `robot` seen through `camera` (its intrinsics and distortion;
// its pose is drawn per sample, or taken from spec.camera_poses, in the fixed frame, which should
// be the robot's root), then the COCO file. Rendering on this thread overlaps with encoding and
// writing on a second one. `progress`, if given, is called with the samples written so far.
// Throws urdfsnap::Error for a file that cannot be written (no annotation file is then written).
void WriteDataset(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const render::CameraSettings& camera,
                  const DatasetSpec& spec, const std::function<void(std::int64_t done)>& progress,
                  Warnings& warnings);

// The pieces WriteDataset is made of, for samples written by worker processes (`dataset --jobs`):
// each worker writes its samples' images and COCO entries, and the parent the COCO file of all.

// Makes spec.folder's images/, depth/ and labels/. Throws urdfsnap::Error.
void MakeSampleFolders(const std::string& folder);

// Writes the samples spec.range (their folders made) and their COCO entries, "images" into
// `images` and "annotations" into `annotations`, each file's entries joined by commas.
void WriteSamples(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const render::CameraSettings& camera,
                  const DatasetSpec& spec, AtomicFile& images, AtomicFile& annotations,
                  const std::function<void(std::int64_t done)>& progress, Warnings& warnings);

// Files of COCO entries as WriteSamples writes them, for a run of samples.
struct CocoParts {
  std::string images, annotations;
};

// Writes spec.annotations_file in spec.folder: the dataset's info (spec.range its samples), the
// entries of `parts` in their order, and the categories of `model`.
void WriteCocoFile(const model::Robot& model, const DatasetSpec& spec, const std::vector<CocoParts>& parts);

// The default --distance: 1 to 2 times the distance at which the robot's bounding sphere in
// its zero pose fills `camera`'s image height.
Interval DefaultDistance(const render::RobotRenderer& robot, const camera::CameraModel& camera);

}  // namespace urdfsnap::dataset
