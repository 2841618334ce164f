// Depth and label sequences: pattern checks, their place in the output plan, the names file.
#include "animation/sequence_outputs.h"

#include <filesystem>
#include <regex>

#include "common/error.h"
#include "common/file_extension.h"
#include "image/image_file_names.h"
#include "video/frame_pattern.h"

namespace urdfsnap::animation {

namespace {

// `example` shows a pattern of the right kind in the message
void CheckFramePattern(const std::string& pattern, const std::string& option, const std::string& example) {
  if (!video::FramePattern::IsPattern(pattern)) {
    throw Error(option + " '" + pattern + "': expected a pattern with the frame number, such as " + example);
  }
  try {
    video::FramePattern checked(pattern);
  } catch (const Error& e) {
    throw Error(option + ": " + e.what());
  }
}

}  // namespace

void CheckDepthPattern(const std::string& pattern, const std::string& option) {
  CheckFramePattern(pattern, option, "depth/%05d.png");
  image::CheckImageFileName(pattern, image::ImageKind::kDepth, option);
}

void CheckLabelsPattern(const std::string& pattern, const std::string& option) {
  CheckFramePattern(pattern, option, "labels/%05d.png");
  image::CheckImageFileName(pattern, image::ImageKind::kLabels, option);
}

void CheckPattern(const std::string& pattern, const std::string& extension, const std::string& option) {
  CheckFramePattern(pattern, option, "frames/%05d" + extension);
  if (LowerCaseExtension(pattern) != extension) {
    throw Error(option + " '" + pattern + "': expected " + extension + " files");
  }
}

void PlanOutput(OutputPlan& plan, const std::string& path, const std::string& role) {
  if (!video::FramePattern::IsPattern(path)) return plan.AddFile(path, role);
  const video::FramePattern pattern(path);
  plan.AddSequence(path, pattern.prefix(), pattern.suffix(), role);
}

std::string LabelNamesPath(const std::string& pattern) {
  const std::filesystem::path path(pattern);
  // the frame number's conversion (FramePattern allows %d or %i, a 0 flag and a width) and the
  // separators around it
  static const std::regex number(R"([-_. ]*%0?[0-9]*[di][-_. ]*)");
  std::string stem = std::regex_replace(path.stem().string(), number, "");
  if (stem.empty()) stem = "labels";
  return (path.parent_path() / (stem + ".json")).string();
}

}  // namespace urdfsnap::animation
