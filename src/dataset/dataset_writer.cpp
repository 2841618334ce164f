// WriteDataset: per sample, draw (joints, camera, render, keypoints) on the GL thread; then encode,
// write and annotate on the pipeline's worker; the COCO file last, atomically.
#include "dataset/dataset_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string_view>

#include "common/atomic_file.h"
#include "common/error.h"
#include "common/version.h"
#include "dataset/camera_json.h"
#include "dataset/coco_regions.h"
#include "dataset/frame_keypoints.h"
#include "dataset/robot_bounds.h"
#include "image/depth_label_files.h"
#include "image/gray16_png.h"
#include "image/png_writer.h"
#include "model/forward_kinematics.h"
#include "stream/pipeline.h"

namespace urdfsnap::dataset {

namespace {

using Json = nlohmann::ordered_json;

struct Sample {
  image::Frame frame;
  std::vector<double> positions;
  Eigen::Isometry3d X_FC;
  std::vector<FrameKeypoint> keypoints;
};

std::string Numbered(std::int64_t k, std::int64_t count) {
  const int digits = std::max<int>(6, static_cast<int>(std::to_string(std::max<std::int64_t>(count - 1, 0)).size()));
  std::string number = std::to_string(k);
  return std::string(static_cast<size_t>(std::max<int>(0, digits - static_cast<int>(number.size()))), '0') + number;
}

// COCO's categories: one per link (id = its label value), then "robot" with the joints as its
// keypoints and the joint tree as its skeleton.
Json Categories(const model::Robot& robot) {
  Json categories = Json::array();
  for (size_t l = 0; l < robot.links().size(); ++l) {
    categories.push_back({{"id", l + 1}, {"name", robot.links()[l].name}, {"supercategory", "link"}});
  }
  Json keypoints = Json::array(), skeleton = Json::array();
  for (size_t j = 0; j < robot.joints().size(); ++j) {
    const model::Joint& joint = robot.joints()[j];
    keypoints.push_back(joint.name);
    // a joint is linked to the joint above it (the one whose child link is its parent link)
    const int above = robot.links()[joint.parent_link].parent_joint;
    if (above >= 0) skeleton.push_back({above + 1, j + 1});
  }
  categories.push_back({{"id", robot.links().size() + 1},
                        {"name", "robot"},
                        {"supercategory", "robot"},
                        {"keypoints", keypoints},
                        {"skeleton", skeleton}});
  return categories;
}

Json Annotation(std::int64_t image_id, int category, std::int64_t id, const Region& region, int width, int height) {
  return {{"id", id},
          {"image_id", image_id},
          {"category_id", category},
          {"bbox", {region.x, region.y, region.width, region.height}},
          {"area", region.area},
          {"segmentation", {{"size", {height, width}}, {"counts", region.counts}}},
          {"iscrowd", 0}};
}

}  // namespace

Interval DefaultDistance(const render::RobotRenderer& robot, const camera::CameraModel& camera) {
  const RobotBounds bounds(robot.scene());
  const std::vector<double> zero(robot.robot().joints().size(), 0.0);
  const double radius = std::max(bounds.Box(model::ComputeLinkPoses(robot.robot(), zero)).diagonal().norm() / 2, 0.01);
  // the sphere's angular radius is half the vertical field of view
  const double half_fov = std::atan(camera.height() / (2 * camera.intrinsics().fy));
  const double fills = radius / std::sin(half_fov);
  return {1.0 * fills, 2.0 * fills};
}

void MakeSampleFolders(const std::string& folder) {
  for (const char* sub : {"images", "depth", "labels"}) {
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(folder) / sub, error);
    if (error) {
      throw Error(SourceLocation{(std::filesystem::path(folder) / sub).string(), 0}, "cannot make the folder: " + error.message());
    }
  }
}

void WriteSamples(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const render::CameraSettings& camera,
                  const DatasetSpec& spec, AtomicFile& images, AtomicFile& annotations,
                  const std::function<void(std::int64_t done)>& progress, Warnings& warnings) {
  const model::Robot& model = robot.robot();
  const RobotBounds bounds(robot.scene());
  const std::filesystem::path folder(spec.folder);
  const int link_count = static_cast<int>(model.links().size());
  const int robot_category = link_count + 1;

  bool first_image = true, first_annotation = true;

  const auto draw = [&](std::int64_t i, Sample& s) {
    const std::int64_t k = spec.range.first + i;
    SampleRandom random(spec.seed, static_cast<std::uint64_t>(k));
    s.positions = SampleJointPositions(model, random, warnings);
    const std::vector<Eigen::Isometry3d> X_RL = model::ComputeLinkPoses(model, s.positions);
    const Eigen::Isometry3d X_FR = X_RL[robot.scene().fixed_link()].inverse();
    render::CameraSettings placed = camera;
    if (spec.camera_poses.empty()) {
      placed.frame.clear();
      placed.pose = SampleCameraPose(X_FR * bounds.Box(X_RL).center(), spec.distance, spec.elevation, random);
    } else {
      placed.pose = spec.camera_poses[static_cast<size_t>(k) % spec.camera_poses.size()];
    }
    s.frame = robot.Render(gl, s.positions, placed, {true, true, true});
    s.X_FC = robot.CameraPose(X_RL, placed);
    s.keypoints = ProjectKeypoints(model, X_RL, X_FR.inverse() * s.X_FC, *camera.model, s.frame.depth, s.frame.labels);
  };
  const auto write = [&](std::int64_t i, const Sample& s) {
    const std::int64_t k = spec.range.first + i;
    const std::string name = Numbered(k, spec.count) + ".png";
    image::WritePng(s.frame.colour, (folder / "images" / name).string());
    image::WriteDepthFile(s.frame.depth, (folder / "depth" / name).string());
    image::WriteGray16Png({s.frame.labels.width, s.frame.labels.height, s.frame.labels.labels},
                          (folder / "labels" / name).string());

    const int w = s.frame.labels.width, h = s.frame.labels.height;
    Json joints = Json::object();
    for (size_t j = 0; j < model.joints().size(); ++j) joints[model.joints()[j].name] = s.positions[j];
    const Json image = {{"id", k},
                        {"file_name", "images/" + name},
                        {"width", w},
                        {"height", h},
                        {"depth_file", "depth/" + name},
                        {"labels_file", "labels/" + name},
                        {"camera", CameraJson(*camera.model, s.X_FC)},
                        {"joints", joints}};
    images.Write((first_image ? "" : ",") + image.dump());
    first_image = false;
    // annotation ids are the image's id times the category count plus the category's: the same
    // whichever shard writes them
    const std::int64_t ids = k * (robot_category + 1);
    for (const Region& region : LabelRegions(s.frame.labels)) {
      const int category = region.label == 0 ? robot_category : region.label;
      Json annotation = Annotation(k, category, ids + category, region, w, h);
      if (region.label == 0) {
        // the joints' keypoints on the robot's annotation, COCO's way: x, y, visibility (0 not in
        // the image, 1 hidden, 2 visible), x = y = 0 when not labelled
        Json flat = Json::array();
        int labelled = 0;
        for (const FrameKeypoint& p : s.keypoints) {
          if (p.kind != FrameKeypoint::Kind::kJoint) continue;
          const int v = !p.in_image ? 0 : p.visible ? 2 : 1;
          flat.push_back(v ? p.uv->x() : 0.0);
          flat.push_back(v ? p.uv->y() : 0.0);
          flat.push_back(v);
          labelled += v > 0;
        }
        annotation["keypoints"] = flat;
        annotation["num_keypoints"] = labelled;
      }
      annotations.Write((first_annotation ? "" : ",") + annotation.dump());
      first_annotation = false;
    }
    if (progress) progress(i + 1);
  };
  stream::RunPipeline<Sample>(spec.range.size(), 2, draw, write);
}

void WriteCocoFile(const model::Robot& model, const DatasetSpec& spec, const std::vector<CocoParts>& parts) {
  // streamed, so memory does not grow with the count
  AtomicFile coco((std::filesystem::path(spec.folder) / spec.annotations_file).string());
  const Json info = {{"description", "urdfsnap dataset of robot '" + model.name() + "'"},
                     {"version", Version()},
                     {"seed", spec.seed},
                     {"count", spec.count},
                     {"samples", {spec.range.first, spec.range.end}}};
  // each part's entries, the parts joined by commas as the entries within them
  const auto copy = [&](const std::string CocoParts::*list) {
    bool first = true;
    std::string chunk(std::size_t{1} << 20, '\0');
    for (const CocoParts& part : parts) {
      std::ifstream in(part.*list, std::ios::binary);
      if (!in) throw Error(part.*list + ": cannot read the samples' annotations");
      bool empty = true;
      while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0) {
        if (empty && !first) coco.Write(",");
        empty = false;
        coco.Write(std::string_view(chunk.data(), static_cast<size_t>(in.gcount())));
      }
      first = first && empty;
    }
  };
  coco.Write("{\"info\":" + info.dump() + ",\"images\":[");
  copy(&CocoParts::images);
  coco.Write("],\"annotations\":[");
  copy(&CocoParts::annotations);
  coco.Write("],\"categories\":" + Categories(model).dump() + "}\n");
  coco.Commit();
}

void WriteDataset(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const render::CameraSettings& camera,
                  const DatasetSpec& spec, const std::function<void(std::int64_t done)>& progress, Warnings& warnings) {
  // the entries into scratch files copied into the COCO file after them (never committed: their
  // destructors remove them); read through their temporary names, written with write(2), unbuffered
  MakeSampleFolders(spec.folder);
  const std::filesystem::path coco = std::filesystem::path(spec.folder) / spec.annotations_file;
  AtomicFile images(coco.string() + ".images"), annotations(coco.string() + ".annotations");
  WriteSamples(robot, gl, camera, spec, images, annotations, progress, warnings);
  WriteCocoFile(robot.robot(), spec, {{images.temp_path(), annotations.temp_path()}});
}

}  // namespace urdfsnap::dataset
