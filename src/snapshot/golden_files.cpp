// WriteGoldens: each golden by its own verdict, in the formats `urdfsnap render` writes.
#include "snapshot/golden_files.h"

#include <filesystem>

#include "common/atomic_file.h"
#include "image/gray16_png.h"
#include "image/png_writer.h"
#include "image/depth_label_files.h"

namespace urdfsnap::snapshot {

namespace {

void CreateFolderOf(const std::string& path) {
  const auto folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder);
}

bool Rewrite(CaseStatus status, bool force) { return force || status != CaseStatus::kPassed; }

}  // namespace

std::vector<std::string> WriteGoldens(const SnapshotCase& c, const CaseResult& result, bool force,
                                      const model::Robot& robot) {
  std::vector<std::string> written;
  if (Rewrite(result.colour_status, force)) {
    CreateFolderOf(c.golden);
    image::WritePng(result.actual, c.golden);
    written.push_back(c.golden);
  }
  const CaseRecord& record = result.record;
  if (record.depth && Rewrite(record.depth->status, force)) {
    CreateFolderOf(c.depth.golden);
    image::WriteGray16Png(result.depth.actual, c.depth.golden);
    written.push_back(c.depth.golden);
  }
  if (record.labels && Rewrite(record.labels->status, force)) {
    CreateFolderOf(c.labels.golden);
    image::WriteGray16Png(result.labels.actual, c.labels.golden);
    const std::string names = std::filesystem::path(c.labels.golden).replace_extension(".json").string();
    WriteFileAtomically(names, image::LabelNamesJson(robot.LinkNames()));
    written.push_back(c.labels.golden);
  }
  return written;
}

}  // namespace urdfsnap::snapshot
