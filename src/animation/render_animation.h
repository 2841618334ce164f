// The render/encode loop of an animation: frame k rendered on the calling thread (which owns the
// GL context) while the frames before it are encoded and written on a worker thread
// (stream::RunPipeline), into the colour encoder and the depth, label, mask and keypoint sequences
// at once. Memory holds a few frames whatever the animation's length.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "animation/animation_frames.h"
#include "common/warnings.h"
#include "gl/scene_renderer.h"
#include "render/robot_renderer.h"
#include "shard/shard_assignment.h"
#include "video/frame_encoder.h"
#include "video/numbered_files.h"

namespace urdfsnap::animation {

// Where the frames go; all but the colour are optional.
struct AnimationOutputs {
  video::FrameEncoder* colour = nullptr;  // required
  video::NumberedFiles* depth = nullptr;     // numbered depth files (.png millimetres or .npy metres)
  video::NumberedFiles* labels = nullptr;    // numbered link-label files (.png)
  video::NumberedFiles* mask = nullptr;      // numbered robot masks (8-bit .png, as `render --mask`)
  int mask_dilate = 0;                    // pixels the masks are grown by
  video::NumberedFiles* keypoints = nullptr; // numbered keypoint files (.json, as `render --keypoints`)
};

// Renders the frames of `range` (the whole animation, or a shard's frames) of `frames` with `robot` through `gl` and writes them, in order, to
// every output; then finishes each output (moving it into place). `progress`, if given, is called with the
// number of the range's frames written so far, after each. At most `depth` rendered frames wait for the
// writer. Warnings of the poses go to `warnings` (touched on the calling thread only). The first
// error on either thread stops both and is rethrown; the outputs are then left unfinished, so that
// their destruction removes what they wrote.
void RenderAnimation(const render::RobotRenderer& robot, gl::SceneRenderer& gl, const AnimationFrames& frames,
                     shard::FrameRange range, const AnimationOutputs& outputs,
                     const std::function<void(std::int64_t done)>& progress,
                     Warnings& warnings, std::size_t depth = 4);

}  // namespace urdfsnap::animation
