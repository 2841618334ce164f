// Keeping markers by namespace and id, and drawing the live ones.
#include "display/marker_display.h"

#include "bag/message_schema.h"
#include "common/error.h"

namespace urdfsnap::display {

MarkerDisplay::MarkerDisplay(std::string topic, MarkerSettings settings, MarkerResources resources)
    : topic_(std::move(topic)), settings_(std::move(settings)), resources_(std::move(resources)) {}

bool MarkerDisplay::Reads(const std::string& type) const {
  return bag::ShortTypeName(type) ==
         (settings_.array ? "visualization_msgs/MarkerArray" : "visualization_msgs/Marker");
}

namespace {

// Whether a marker received at `received_ns` is gone at `time_ns` (its lifetime passed).
bool Expired(const Marker& m, std::int64_t received_ns, std::int64_t time_ns) {
  return m.lifetime_ns > 0 && time_ns > received_ns + m.lifetime_ns;
}

}  // namespace

void MarkerDisplay::Receive(const bag::MessageValue& message, std::int64_t time_ns,
                            const std::string& where, Warnings& warnings) {
  Expire(time_ns);
  if (!settings_.array) {
    Apply(DecodeMarker(message), time_ns, where, warnings);
    return;
  }
  for (Marker& marker : DecodeMarkerArray(message)) Apply(std::move(marker), time_ns, where, warnings);
}

void MarkerDisplay::Expire(std::int64_t time_ns) {
  std::erase_if(markers_, [&](const auto& entry) {
    return Expired(entry.second.marker, entry.second.received_ns, time_ns);
  });
}

void MarkerDisplay::Apply(Marker marker, std::int64_t time_ns, const std::string& where,
                          Warnings& warnings) {
  const std::string name = "marker '" + marker.ns + "/" + std::to_string(marker.id) + "'";
  switch (marker.action) {
    case Marker::kAdd: {
      const std::string problem = MarkerProblem(marker);
      if (!problem.empty()) {
        warnings.Add(where + ": " + name + ": " + problem + "; not drawn");
        return;
      }
      std::pair<std::string, int> key{marker.ns, marker.id};
      MarkerMeshes meshes = MakeMarkerMeshes(marker);
      markers_.insert_or_assign(std::move(key), Kept{std::move(marker), std::move(meshes), time_ns, where});
      return;
    }
    case Marker::kDelete: markers_.erase({marker.ns, marker.id}); return;
    case Marker::kDeleteAll: markers_.clear(); return;
    default:
      warnings.Add(where + ": " + name + ": unknown action " + std::to_string(marker.action) + "; ignored");
  }
}

void MarkerDisplay::Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
                         Warnings& warnings) const {
  const size_t first_label = scene.labels.size();
  for (const auto& [key, kept] : markers_) {
    const Marker& m = kept.marker;
    if (Expired(m, kept.received_ns, time_ns)) continue;
    const auto shown = settings_.namespaces.find(m.ns);
    if (shown != settings_.namespaces.end() && !shown->second) continue;
    const std::string name = "marker '" + m.ns + "/" + std::to_string(m.id) + "'";
    const std::optional<Eigen::Isometry3d> X_FH =
        lookup(m.header.frame_id, m.frame_locked ? time_ns : LookupTime(m.header.stamp_ns, kept.received_ns));
    if (!X_FH) {
      warnings.Add(kept.where + ": " + name + ": no transform from frame '" + m.header.frame_id +
                   "' to the fixed frame; not drawn");
      continue;
    }
    try {
      AddMarker(m, kept.meshes, *X_FH, resources_, scene);
    } catch (const Error& e) {
      warnings.Add(kept.where + ": " + name + ": " + e.what() + "; not drawn");
    }
  }
  std::vector<std::shared_ptr<const texture::TextureImage>> drawn_text;
  for (size_t i = first_label; i < scene.labels.size(); ++i) drawn_text.push_back(scene.labels[i].texture);
  const std::lock_guard<std::mutex> lock(drawn_text_mutex_);
  drawn_text_ = std::move(drawn_text);
}

}  // namespace urdfsnap::display
