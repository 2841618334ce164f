// RenderAnimation: RunPipeline with image::Frame items (colour, and depth and labels when asked).
#include "animation/render_animation.h"

#include <string>

#include "image/depth_label_files.h"
#include "stream/pipeline.h"

namespace urdfsnap::animation {

void RenderAnimation(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const AnimationFrames& frames,
                     shard::FrameRange range, const AnimationOutputs& outputs, stream::ProgressBar* progress,
                     Warnings& warnings, std::size_t depth) {
  const image::FrameOutputs wanted{true, outputs.depth != nullptr, outputs.labels != nullptr};
  const auto render = [&](std::int64_t i, image::Frame& frame) {
    const std::int64_t k = range.first + i;
    frame = frames.camera() ? robot.Render(gl, frames.Positions(k, warnings), *frames.camera(), wanted)
                            : gl.Render(frames.Scene(robot, k, warnings), frames.View(k), frames.size().width,
                                        frames.size().height, wanted);
  };
  const auto write = [&](std::int64_t i, const image::Frame& frame) {
    outputs.colour->Write(frame.colour);
    if (outputs.depth) {
      outputs.depth->Write(image::EncodeDepthFile(frame.depth, outputs.depth->pattern().pattern()));
    }
    if (outputs.labels) outputs.labels->Write(image::EncodeLabels(frame.labels));
    if (progress) progress->Update(i + 1);
  };
  stream::RunPipeline<image::Frame>(range.size(), depth, render, write);
  outputs.colour->Finish();
  if (outputs.depth) outputs.depth->Finish();
  if (outputs.labels) outputs.labels->Finish();
}

}  // namespace urdfsnap::animation
