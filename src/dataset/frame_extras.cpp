// MakeFrameExtras: the mask from the label image, the keypoints against depth and labels.
#include "dataset/frame_extras.h"

#include "camera/robot_mask.h"
#include "common/error.h"
#include "dataset/rendered_keypoints.h"

namespace urdfsnap::dataset {

void CheckMaskDilate(int pixels, const std::string& option) {
  if (pixels < 0 || pixels > kMaxMaskDilate) {
    throw Error(option + " " + std::to_string(pixels) + ": expected a number of pixels from 0 to " +
                std::to_string(kMaxMaskDilate));
  }
}

image::FrameOutputs OutputsFor(image::FrameOutputs outputs, const ExtrasWanted& wanted) {
  outputs.depth = outputs.depth || wanted.keypoints;
  outputs.labels = outputs.labels || wanted.mask || wanted.keypoints;
  return outputs;
}

FrameExtras MakeFrameExtras(const ExtrasWanted& wanted, const render::RobotRenderer& robot,
                            const std::vector<double>& positions, const render::CameraSettings& camera,
                            const image::Frame& frame) {
  FrameExtras extras;
  if (wanted.mask) extras.mask = camera::RobotMask(frame.labels, wanted.mask_dilate);
  if (wanted.keypoints) extras.keypoints = RenderedKeypointsJson(robot, positions, camera, frame, wanted.keypoints_indent);
  return extras;
}

}  // namespace urdfsnap::dataset
