// RViz's PointCloud2 and LaserScan displays (point_cloud2_display.cpp, laser_scan_display.cpp,
// both drawing through point_cloud_common.cpp): the clouds of their topic received within Decay
// Time of the time drawn (the latest one only with the default 0), each placed by TF at its header
// stamp and drawn as a scene::PointSet. A scan is projected into a cloud when drawn, each beam at
// its own time (laser_scan.h).
#pragma once

#include <deque>
#include <string>
#include <variant>

#include "display/display.h"
#include "display/display_settings.h"
#include "display/point_cloud_message.h"

namespace urdfsnap::display {

class PointCloudDisplay : public Display {
 public:
  PointCloudDisplay(std::string topic, CloudSettings settings);

  const std::string& topic() const override { return topic_; }
  bool Reads(const std::string& type) const override;
  void Receive(const bag::MessageValue& message, std::int64_t time_ns, const std::string& where,
               Warnings& warnings) override;
  // A cloud whose claims do not fit its bytes, or without a transform, is a warning naming the
  // message and is not drawn.
  void Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
            Warnings& warnings) const override;

  // Keeps `message` received at `time_ns` (Receive's decoded message; the tests' entry).
  void Keep(std::variant<PointCloud2, LaserScan> message, std::int64_t time_ns, const std::string& where);

 private:
  struct Kept {
    std::variant<PointCloud2, LaserScan> message;
    std::int64_t received_ns;
    std::string where;
  };
  std::int64_t DecayNanoseconds() const;
  std::string topic_;
  CloudSettings settings_;
  std::deque<Kept> kept_;
};

}  // namespace urdfsnap::display
