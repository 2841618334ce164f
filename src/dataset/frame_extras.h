// What a frame gives besides its colour, depth and label images, the same way for `render`,
// `animate` and Python: the robot's mask (camera::RobotMask) and the keypoints file's text
// (keypoints_file.h), both made from the frame's own depth and label images.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"
#include "render/robot_renderer.h"

namespace urdfsnap::dataset {

inline constexpr int kMaxMaskDilate = 1000;

struct ExtrasWanted {
  bool mask = false;
  int mask_dilate = 0;          // pixels, 0 to kMaxMaskDilate (CheckMaskDilate)
  bool keypoints = false;
  int keypoints_indent = 2;     // the JSON's indent; -1 for one line (JSON Lines)
};

struct FrameExtras {
  image::Gray8Image mask;       // empty unless asked for
  std::string keypoints;        // the keypoints file's text; empty unless asked for
};

// Throws urdfsnap::Error naming `option` when `pixels` is outside 0..kMaxMaskDilate.
void CheckMaskDilate(int pixels, const std::string& option);

// The images `outputs` asks for and those `wanted` needs: labels for the mask, depth and labels
// for the keypoints' visibility.
image::FrameOutputs OutputsFor(image::FrameOutputs outputs, const ExtrasWanted& wanted);

// The extras of `frame`, drawn by `robot` at `positions` through `camera` (the calibrated camera,
// or render::OrbitCamera of the view drawn) with the images OutputsFor asks for.
FrameExtras MakeFrameExtras(const ExtrasWanted& wanted, const render::RobotRenderer& robot,
                            const std::vector<double>& positions, const render::CameraSettings& camera,
                            const image::Frame& frame);

}  // namespace urdfsnap::dataset
