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
  Keep(settings_.laser_scan ? ProjectLaserScan(DecodeLaserScan(message)) : DecodePointCloud2(message), time_ns, where);
}

std::int64_t PointCloudDisplay::DecayNanoseconds() const {
  const double decay = settings_.points.decay_time;
  return decay > 0 && std::isfinite(decay) ? static_cast<std::int64_t>(std::min(decay, 1e9) * 1e9) : 0;
}

void PointCloudDisplay::Keep(PointCloud2 cloud, std::int64_t time_ns, const std::string& where) {
  kept_.push_back({std::move(cloud), time_ns, where});
  // what no later draw can show: older than the decay time at the newest cloud's time
  while (kept_.size() > 1 && time_ns - kept_.front().received_ns >= DecayNanoseconds()) kept_.pop_front();
}

void PointCloudDisplay::Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
                             Warnings& warnings) const {
  for (size_t i = 0; i < kept_.size(); ++i) {
    const Kept& kept = kept_[i];
    // point_cloud_common.cpp update: clouds as old as the decay time go, the newest always stays
    if (i + 1 < kept_.size() && time_ns - kept.received_ns >= DecayNanoseconds()) continue;
    const std::optional<Eigen::Isometry3d> X_FC =
        lookup(kept.cloud.frame_id, LookupTime(kept.cloud.stamp_ns, kept.received_ns));
    if (!X_FC) {
      warnings.Add(kept.where + ": no transform from frame '" + kept.cloud.frame_id + "' to the fixed frame; not drawn");
      continue;
    }
    try {
      scene.points.push_back(CloudPointSet(kept.cloud, settings_.points, *X_FC));
    } catch (const CloudError& e) {
      warnings.Add(kept.where + ": " + e.what() + "; not drawn");
    }
  }
}

}  // namespace urdfsnap::display
