// The depth and link-label images as files, in the conventions of the robotics field:
//   depth .png: 16-bit, millimetres along the camera's viewing axis, 0 where no robot is (ROS's
//               16UC1 depth images), values beyond 65.535 m saturate at 65535;
//   depth .npy: float32 metres, NaN where no robot is (ROS's 32FC1), read by numpy.load;
//   labels .png: 16-bit, 1 + the link's index (Robot::links() order, as `urdfsnap info` lists the
//               links), 0 where none; with FILE.json beside FILE.png mapping each value (a decimal
//               string) to the link's name.
// As bytes: the command writing them plans its outputs (common/output_plan.h) and writes them all
// or none.
#pragma once

#include <string>

#include "image/image.h"
#include "model/robot.h"

namespace urdfsnap::render {

// Millimetres as the 16-bit depth PNG stores them (0 where there is no robot).
image::Gray16Image DepthMillimetres(const image::DepthImage& depth);

// The bytes of the depth file `path` for `depth`, by its extension (.png or .npy). Throws
// urdfsnap::Error naming the path for another extension.
std::string DepthFileBytes(const image::DepthImage& depth, const std::string& path);

// The bytes of a label image file (.png).
std::string LabelFileBytes(const image::LabelImage& labels);

// The JSON object {"1": "base_link", "2": ...} for every link of `robot`.
std::string LabelNamesJson(const model::Robot& robot);

// Where the link names of the label image `path` go: beside it, the same name with .json.
std::string LabelNamesFile(const std::string& path);

// For C++ API users writing one frame's files: DepthFileBytes into `path`, and LabelFileBytes into
// `path` with LabelNamesJson into LabelNamesFile(path), each atomically (temporary file + rename).
// Throws urdfsnap::Error naming the path. (The commands plan all their outputs together instead.)
void WriteDepthFile(const image::DepthImage& depth, const std::string& path);
void WriteLabelFiles(const image::LabelImage& labels, const model::Robot& robot, const std::string& path);

// Throws urdfsnap::Error naming `option` unless `path` has an extension DepthFileBytes (depth) or
// LabelFileBytes (labels, .png) takes: for checking command-line options before rendering.
void CheckDepthPath(const std::string& path, const std::string& option);
void CheckLabelsPath(const std::string& path, const std::string& option);

}  // namespace urdfsnap::render
