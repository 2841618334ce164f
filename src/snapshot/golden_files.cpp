// WriteGoldens: each golden by its own verdict, in the formats `urdfsnap render` writes.
#include "snapshot/golden_files.h"

#include "image/gray16_png.h"
#include "image/png_writer.h"
#include "image/depth_label_files.h"
#include "snapshot/golden_camera.h"

namespace urdfsnap::snapshot {

namespace {

bool Rewrite(CaseStatus status, bool force) { return force || status != CaseStatus::kPassed; }

}  // namespace

void PlanGoldens(OutputPlan& outputs, const SnapshotCase& c) {
  const std::string role = "the golden of case '" + c.name + "'";
  outputs.AddFile(c.golden, role);
  if (c.request.camera_info.empty()) outputs.AddFile(GoldenCameraFile(c.golden), "the camera of case '" + c.name + "'");
  if (c.depth.wanted) outputs.AddFile(c.depth.golden, "the depth golden of case '" + c.name + "'");
  if (c.labels.wanted) {
    outputs.AddFile(c.labels.golden, "the labels golden of case '" + c.name + "'");
    outputs.AddFile(image::LabelNamesFile(c.labels.golden), "the link names of case '" + c.name + "'");
  }
}

std::vector<std::string> WriteGoldens(OutputPlan& outputs, const SnapshotCase& c, const CaseResult& result,
                                      bool force, const model::Robot& robot) {
  std::vector<std::string> written;
  if (Rewrite(result.colour_status, force)) {
    outputs.Write(c.golden, image::EncodePng(result.actual));
    written.push_back(c.golden);
  }
  if (result.view && (Rewrite(result.colour_status, force) || !result.camera_file_current)) {
    outputs.Write(GoldenCameraFile(c.golden), GoldenCameraJson(*result.view));
    written.push_back(GoldenCameraFile(c.golden));
  }
  const CaseRecord& record = result.record;
  if (record.depth && Rewrite(record.depth->status, force)) {
    outputs.Write(c.depth.golden, image::EncodeGray16Png(result.depth.actual));
    written.push_back(c.depth.golden);
  }
  if (record.labels && Rewrite(record.labels->status, force)) {
    outputs.Write(c.labels.golden, image::EncodeGray16Png(result.labels.actual));
    outputs.Write(image::LabelNamesFile(c.labels.golden), image::LabelNamesJson(robot.LinkNames()));
    written.push_back(c.labels.golden);
  }
  return written;
}

}  // namespace urdfsnap::snapshot
