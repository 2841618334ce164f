// Keeping clouds for their decay time and drawing them through TF.
#include "display/point_cloud_display.h"

#include <algorithm>
#include <cmath>

#include "bag/message_schema.h"
#include "display/laser_scan.h"
#include "display/point_cloud.h"
#include "display/point_cloud_reader.h"

namespace urdfsnap::display {

PointCloudDisplay::PointCloudDisplay(std::string topic, CloudSettings settings)
    : topic_(std::move(topic)), settings_(std::move(settings)) {}

bool PointCloudDisplay::Reads(const std::string& type) const {
  return bag::ShortTypeName(type) == (settings_.laser_scan ? "sensor_msgs/LaserScan" : "sensor_msgs/PointCloud2");
}

void PointCloudDisplay::Receive(const bag::MessageValue& message, std::int64_t time_ns, const std::string& where,
                                Warnings& /*warnings*/) {
  if (settings_.laser_scan) {
    Keep(DecodeLaserScan(message), time_ns, where);
  } else {
    Keep(DecodePointCloud2(message), time_ns, where);
  }
}

std::int64_t PointCloudDisplay::DecayNanoseconds() const {
  const double decay = settings_.points.decay_time;
  return decay > 0 && std::isfinite(decay) ? static_cast<std::int64_t>(std::min(decay, 1e9) * 1e9) : 0;
}

void PointCloudDisplay::Keep(std::variant<PointCloud2, LaserScan> message, std::int64_t time_ns,
                             const std::string& where) {
  kept_.push_back({std::move(message), time_ns, where});
  // what no later draw can show: older than the decay time at the newest cloud's time
  while (kept_.size() > 1 && time_ns - kept_.front().received_ns >= DecayNanoseconds()) kept_.pop_front();
}

void PointCloudDisplay::Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
                             Warnings& warnings) const {
  for (size_t i = 0; i < kept_.size(); ++i) {
    const Kept& kept = kept_[i];
    // point_cloud_common.cpp update: clouds as old as the decay time go, the newest always stays
    if (i + 1 < kept_.size() && time_ns - kept.received_ns >= DecayNanoseconds()) continue;
    const auto& [frame, stamp_ns] = std::visit([](const auto& m) { return std::pair(m.frame_id, m.stamp_ns); }, kept.message);
    const std::optional<Eigen::Isometry3d> X_FC = lookup(frame, LookupTime(stamp_ns, kept.received_ns));
    const LaserScan* scan = std::get_if<LaserScan>(&kept.message);
    // laser_scan_display.cpp: the scan's last beam is placed at its own time too
    const std::optional<Eigen::Isometry3d> X_FC_end =
        scan ? lookup(frame, LookupTime(LastBeamStamp(*scan), kept.received_ns)) : X_FC;
    if (!X_FC || !X_FC_end) {
      warnings.Add(kept.where + ": no transform from frame '" + frame + "' to the fixed frame; not drawn");
      continue;
    }
    try {
      if (scan) {
        scene.points.push_back(
            CloudPointSet(ProjectLaserScan(*scan, *X_FC, *X_FC_end), settings_.points, Eigen::Isometry3d::Identity()));
      } else {
        scene.points.push_back(CloudPointSet(std::get<PointCloud2>(kept.message), settings_.points, *X_FC));
      }
    } catch (const CloudError& e) {
      warnings.Add(kept.where + ": " + e.what() + "; not drawn");
    }
  }
}

}  // namespace urdfsnap::display
