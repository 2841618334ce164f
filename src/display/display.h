// The common shape of an RViz display in urdfsnap: it takes the messages of its topic as they are
// received, keeping what RViz would keep, and adds what it shows at a time to a scene in the fixed
// frame, looking each message's frame up through TF at the message's stamp as RViz's
// FrameManager does. Markers, Path, PoseArray, Axes, PointCloud2 and LaserScan are displays
// (display/make_display.h).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "bag/cdr_message.h"
#include "common/warnings.h"
#include "scene/scene.h"

namespace urdfsnap::display {

// Where frame `frame` is in the fixed frame at `stamp_ns`; nothing when TF does not know.
using FrameLookup = std::function<std::optional<Eigen::Isometry3d>(const std::string& frame,
                                                                   std::int64_t stamp_ns)>;

class Display {
 public:
  virtual ~Display() = default;

  // The topic it subscribes to ("" for none) and whether it reads messages of `type`
  // ("pkg/msg/Type" or "pkg/Type").
  virtual const std::string& topic() const = 0;
  virtual bool Reads(const std::string& type) const = 0;

  // Takes a decoded message received at `time_ns`; `where` names it in warnings ("run.mcap:
  // message 3 on '/markers'"). Throws bag::CdrError when its definition lacks a field read.
  virtual void Receive(const bag::MessageValue& message, std::int64_t time_ns, const std::string& where,
                       Warnings& warnings) = 0;

  // Adds what the display shows at `time_ns` to `scene`; what cannot be drawn (no transform, a
  // broken marker, a mesh that does not load) is a warning naming the message.
  virtual void Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
                    Warnings& warnings) const = 0;
};

// The time a message's frame is looked up at: its header stamp, or the time it was received when
// the stamp is 0 (RViz's "latest transform").
inline std::int64_t LookupTime(std::int64_t stamp_ns, std::int64_t received_ns) {
  return stamp_ns != 0 ? stamp_ns : received_ns;
}

}  // namespace urdfsnap::display
