// RenderAnimation: RunPipeline with image::Frame items (colour, and depth and labels when asked).
#include "animation/render_animation.h"

#include <filesystem>
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
    const std::vector<double> positions = frames.Positions(k, warnings);
    frame = frames.camera() ? robot.Render(gl, positions, *frames.camera(), wanted)
                            : robot.Render(gl, positions, frames.View(k), frames.size(), wanted,
                                           frames.Place(k, warnings));
  };
  // the depth files' format, by the pattern's extension as `render --depth FILE` decides it
  const std::string depth_extension =
      outputs.depth ? std::filesystem::path(outputs.depth->pattern().pattern()).extension().string() : "";
  const auto write = [&](std::int64_t i, const image::Frame& frame) {
    outputs.colour->Write(frame.colour);
    if (outputs.depth) {
      outputs.depth->Write(image::EncodeDepth(frame.depth, depth_extension));
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
