// RenderAnimation: RunPipeline with the frames' images (colour, and depth and labels when asked)
// and keypoints; masks are made on the writer's thread.
#include "animation/render_animation.h"

#include <string>

#include "camera/robot_mask.h"
#include "dataset/frame_extras.h"
#include "dataset/rendered_keypoints.h"
#include "image/depth_label_files.h"
#include "image/png_writer.h"
#include "stream/pipeline.h"

namespace urdfsnap::animation {

namespace {

// One frame on its way from the renderer to the writer.
struct DrawnFrame {
  image::Frame frame;
  std::string keypoints;   // the keypoint file's text, when asked for
};

// The camera frame `k` is seen through, with its pose in the robot's fixed frame: the calibrated
// camera, or the orbit view as one (moved into the robot's fixed frame when `X_SF` places it).
render::CameraSettings FrameCamera(const AnimationFrames& frames, std::int64_t k,
                                   const std::optional<render::CameraSettings>& calibrated, const Eigen::Isometry3d& X_SF) {
  if (calibrated) return *calibrated;
  render::CameraSettings camera = render::OrbitCamera(frames.View(k), frames.size().width, frames.size().height);
  camera.pose = X_SF.inverse() * camera.pose;
  return camera;
}

}  // namespace

void RenderAnimation(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const AnimationFrames& frames,
                     shard::FrameRange range, const AnimationOutputs& outputs,
                     const std::function<void(std::int64_t done)>& progress,
                     Warnings& warnings, std::size_t depth) {
  const image::FrameOutputs wanted = dataset::OutputsFor(
      {true, outputs.depth != nullptr, outputs.labels != nullptr},
      {outputs.mask != nullptr, outputs.mask_dilate, outputs.keypoints != nullptr});
  const auto render = [&](std::int64_t i, DrawnFrame& drawn) {
    const std::int64_t k = range.first + i;
    const std::vector<double> positions = frames.Positions(k, warnings);
    const std::optional<render::CameraSettings> camera = frames.Camera(k, warnings);
    // the scene with its displays, through the camera on the placed robot or through the view
    const scene::Scene scene = frames.Scene(robot, k, warnings);
    drawn.frame = camera ? robot.Render(gl, scene, frames.Place(k, warnings), positions, *camera, wanted)
                         : gl.Render(scene, frames.View(k), frames.size().width, frames.size().height, wanted);
    const Eigen::Isometry3d X_SF = camera ? Eigen::Isometry3d::Identity() : frames.Place(k, warnings);
    if (outputs.keypoints) {
      drawn.keypoints =
          dataset::RenderedKeypointsJson(robot, positions, FrameCamera(frames, k, camera, X_SF), drawn.frame);
    }
  };
  const auto write = [&](std::int64_t i, const DrawnFrame& drawn) {
    const image::Frame& frame = drawn.frame;
    outputs.colour->Write(frame.colour);
    if (outputs.depth) {
      outputs.depth->Write(image::EncodeDepthFile(frame.depth, outputs.depth->pattern().pattern()));
    }
    if (outputs.labels) outputs.labels->Write(image::EncodeLabels(frame.labels));
    if (outputs.mask) {
      const std::vector<std::uint8_t> png = image::EncodeGray8Png(camera::RobotMask(frame.labels, outputs.mask_dilate));
      outputs.mask->Write({reinterpret_cast<const char*>(png.data()), png.size()});
    }
    if (outputs.keypoints) outputs.keypoints->Write(drawn.keypoints);
    if (progress) progress(i + 1);
  };
  stream::RunPipeline<DrawnFrame>(range.size(), depth, render, write);
  outputs.colour->Finish();
  for (video::NumberedFiles* files : {outputs.depth, outputs.labels, outputs.mask, outputs.keypoints}) {
    if (files) files->Finish();
  }
}

}  // namespace urdfsnap::animation
