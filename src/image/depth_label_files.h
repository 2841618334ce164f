// The depth and link-label images as files, in the conventions of the robotics field:
//   depth .png: 16-bit, millimetres along the camera's viewing axis, 0 where no robot is (ROS's
//               16UC1 depth images), values beyond 65.535 m saturate at 65535;
//   depth .npy: float32 metres, NaN where no robot is (ROS's 32FC1), read by numpy.load;
//   labels .png: 16-bit, 1 + the link's index (Robot::links() order, as `urdfsnap info` lists the
//               links), 0 where none; with FILE.json beside FILE.png mapping each value (a decimal
//               string) to the link's name.
// One encoder per format, used for single files (`render --depth/--labels`, whose outputs the
// command plans and writes all or none, common/output_plan.h) and for an animation's numbered
// sequences alike.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace urdfsnap::image {

// Millimetres as the 16-bit depth PNG stores them (0 where there is no robot).
Gray16Image DepthMillimetres(const DepthImage& depth);

// The bytes of the depth file `path` (or of a numbered sequence's pattern such as depth/%05d.npy),
// its format chosen by its extension: ".png", 16-bit millimetres; ".npy", float32 metres. The one
// place that choice is made. Throws urdfsnap::Error naming the path for another extension.
std::string EncodeDepthFile(const DepthImage& depth, const std::string& path);

// The bytes of a 16-bit label PNG.
std::string EncodeLabels(const LabelImage& labels);

// The JSON object {"1": "base_link", "2": ...} for the links named `link_names`, in order.
std::string LabelNamesJson(const std::vector<std::string>& link_names);

// Writes `depth` to `path` by its extension (.png or .npy). Throws urdfsnap::Error naming the
// path for another extension or a write failure.
void WriteDepthFile(const DepthImage& depth, const std::string& path);

// Writes `labels` to `path` (which must end in .png) and LabelNamesJson beside it (same name,
// .json). Throws urdfsnap::Error naming the path.
void WriteLabelFiles(const LabelImage& labels, const std::vector<std::string>& link_names, const std::string& path);

// Where the link names of the label image `path` go: beside it, the same name with .json.
std::string LabelNamesFile(const std::string& path);

}  // namespace urdfsnap::image
