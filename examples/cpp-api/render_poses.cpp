// Renders 100 poses of one robot through urdfsnap's typed C++ API: the model is loaded once, the
// robot prepared once (meshes, textures, colours), the view fitted once over all poses (so the
// camera does not jump), then each frame is one call. Writes OUT_DIR/pose_000.png ... pose_099.png,
// for the first pose its depth (metres, .npy) and link-label images, and OUT_DIR/pose_000.args:
// the `urdfsnap render` options that draw the first pose from the same view.
// usage: render_poses MODEL OUT_DIR     (MODEL: a URDF or xacro file)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common/error.h"
#include "gl/scene_renderer.h"
#include "image/png_writer.h"
#include "model/joint_values.h"
#include "image/depth_label_files.h"
#include "render/robot_renderer.h"
#include "request/model_request.h"

namespace us = urdfsnap;

// `urdfsnap render` options, one per line, for these joint positions, view and size.
void WriteRenderArguments(const us::model::Robot& robot, const std::vector<double>& positions,
                          const us::scene::OrbitView& view, us::render::ImageSize size, const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file) throw us::Error(path + ": cannot write");
  std::fprintf(file, "--size\n%dx%d\n--yaw\n%.17g\n--pitch\n%.17g\n--distance\n%.17g\n--focal\n%.17g,%.17g,%.17g\n",
               size.width, size.height, view.yaw, view.pitch, view.distance, view.focal.x(), view.focal.y(),
               view.focal.z());
  for (const std::string& name : robot.MovableJointNames()) {
    std::fprintf(file, "-j\n%s=%.17g\n", name.c_str(), positions[robot.FindJoint(name)]);
  }
  std::fclose(file);
}

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: render_poses MODEL OUT_DIR\n");
    return 2;
  }
  const std::string model_path = argv[1], out = argv[2];
  try {
    us::Warnings warnings;
    const std::shared_ptr<const us::model::Robot> robot = us::request::LoadModel({model_path}, warnings).robot;

    us::render::RenderSettings settings;   // RViz's defaults
    settings.scene.model_file = model_path;  // meshes are found relative to it
    settings.size = {480, 360};
    const us::render::RobotRenderer arm(robot, settings.scene, warnings);
    us::gl::SceneRenderer gl(settings.samples);

    // every movable joint swings through half its range (or ±1 rad) over the 100 poses
    const auto pose = [&](int k) {
      us::model::NamedValues values;
      for (const std::string& name : robot->MovableJointNames()) {
        const us::model::Joint& joint = robot->joints()[robot->FindJoint(name)];
        const double middle = joint.has_limits ? (joint.lower + joint.upper) / 2 : 0;
        const double swing = joint.has_limits ? (joint.upper - joint.lower) / 4 : 1;
        values.emplace_back(name, middle + swing * std::sin(2 * M_PI * k / 100.0));
      }
      return us::model::ResolveJointPositions(*robot, values, true, warnings);
    };
    const us::scene::OrbitView view = arm.FitView(us::render::Fit::kFit, settings.fit_margin, settings.view, settings.size, 100, pose);

    std::filesystem::create_directories(out);
    for (int k = 0; k < 100; ++k) {
      const us::image::FrameOutputs outputs{true, k == 0, k == 0};
      const us::image::Frame frame = arm.Render(gl, pose(k), view, settings.size, outputs);
      char name[32];
      std::snprintf(name, sizeof name, "/pose_%03d.png", k);
      us::image::WritePng(frame.colour, out + name);
      if (k == 0) {
        us::image::WriteDepthFile(frame.depth, out + "/pose_000_depth.npy");
        us::image::WriteLabelFiles(frame.labels, robot->LinkNames(), out + "/pose_000_labels.png");
        WriteRenderArguments(*robot, pose(0), view, settings.size, out + "/pose_000.args");
      }
    }
    for (const std::string& message : warnings.messages()) std::fprintf(stderr, "warning: %s\n", message.c_str());
  } catch (const us::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  std::printf("wrote 100 poses to %s\n", out.c_str());
  return 0;
}
