// Keeping the last pose lists of a topic and placing them through TF.
#include "display/pose_list_display.h"

#include "bag/message_schema.h"

namespace urdfsnap::display {

PoseListDisplay::PoseListDisplay(std::string topic, std::string type, size_t keep)
    : topic_(std::move(topic)), type_(std::move(type)), keep_(std::max<size_t>(1, keep)) {}

bool PoseListDisplay::Reads(const std::string& type) const { return bag::ShortTypeName(type) == type_; }

void PoseListDisplay::Receive(const bag::MessageValue& message, std::int64_t time_ns,
                              const std::string& where, Warnings& warnings) {
  Keep(type_ == "nav_msgs/Path" ? DecodePath(message) : DecodePoseArray(message), time_ns, where, warnings);
}

void PoseListDisplay::Keep(PoseList poses, std::int64_t time_ns, const std::string& where,
                           Warnings& warnings) {
  // path_display.cpp and pose_array_display.cpp validate every number before drawing
  bool finite = true;
  for (const Pose& p : poses.poses) finite = finite && p.position.allFinite() && p.orientation.coeffs().allFinite();
  if (!finite) {
    warnings.Add(where + ": message contains invalid floating point values (nans or infs); not drawn");
    return;
  }
  kept_.push_back({std::move(poses), time_ns, where});
  while (kept_.size() > keep_) kept_.pop_front();
}

void PoseListDisplay::Draw(std::int64_t /*time_ns*/, const FrameLookup& lookup, scene::Scene& scene,
                           Warnings& warnings) const {
  for (const Kept& kept : kept_) {
    const Header& header = kept.poses.header;
    const std::optional<Eigen::Isometry3d> X_FH = lookup(header.frame_id, LookupTime(header.stamp_ns, kept.received_ns));
    if (!X_FH) {
      warnings.Add(kept.where + ": no transform from frame '" + header.frame_id + "' to the fixed frame; not drawn");
      continue;
    }
    DrawPoses(kept.poses, *X_FH, scene);
  }
}

}  // namespace urdfsnap::display
