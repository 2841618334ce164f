// The sequences beside an animation (`--depth`, `--labels`, `--mask`, `--keypoints`): numbered files
// (video::NumberedFiles) in the formats `render --depth/--labels/--mask/--keypoints` writes, one per
// frame, from the same renders as the colour frames.
#pragma once

#include <string>

#include "common/output_plan.h"

namespace urdfsnap::animation {

// Throw urdfsnap::Error naming `option` unless `pattern` is a frame pattern (one %d, see
// video::FramePattern) of a depth file (.png or .npy) or a label file (.png).
void CheckDepthPattern(const std::string& pattern, const std::string& option);
void CheckLabelsPattern(const std::string& pattern, const std::string& option);
// Likewise for a sequence of files with `extension` (".png" masks, ".json" keypoints).
void CheckPattern(const std::string& pattern, const std::string& extension, const std::string& option);

// Adds the output `path` to `plan`: the numbered files of a frame pattern, or one file.
void PlanOutput(OutputPlan& plan, const std::string& path, const std::string& role);

// Where a label sequence's link names (image::LabelNamesJson) go, once for the whole sequence:
// the pattern without its frame number and the separator before it, as .json
// ("out/label_%04d.png" -> "out/label.json"); "labels.json" in the folder when nothing is left
// ("labels/%05d.png" -> "labels/labels.json").
std::string LabelNamesPath(const std::string& pattern);

}  // namespace urdfsnap::animation
