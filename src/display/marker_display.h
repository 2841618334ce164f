// RViz's Marker and MarkerArray displays (marker_display.cpp, marker_array_display.cpp): markers
// kept by namespace and id as they arrive, ADD and MODIFY replacing the one of the same id, DELETE
// removing it, DELETEALL removing every marker; a marker disappears once its lifetime has passed
// since it was received. A marker that is not frame_locked stays where TF put it at its stamp;
// a frame_locked one follows its frame at the time drawn.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "display/display.h"
#include "display/display_settings.h"
#include "display/marker_shapes.h"

namespace urdfsnap::display {

class MarkerDisplay : public Display {
 public:
  MarkerDisplay(std::string topic, MarkerSettings settings, MarkerResources resources);

  const std::string& topic() const override { return topic_; }
  bool Reads(const std::string& type) const override;
  void Receive(const bag::MessageValue& message, std::int64_t time_ns, const std::string& where,
               Warnings& warnings) override;
  void Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
            Warnings& warnings) const override;

  // Applies one marker's action as received at `time_ns` (the message decoders' entry, and the
  // tests'); a marker RViz refuses is a warning and is not kept.
  void Apply(Marker marker, std::int64_t time_ns, const std::string& where, Warnings& warnings);

  // Drops the markers whose lifetime has passed at `time_ns`, which no later draw shows, so that a
  // long recording keeps only the live ones (Receive does it first).
  void Expire(std::int64_t time_ns);

  // How many markers are kept.
  size_t size() const { return markers_.size(); }

 private:
  struct Kept {
    Marker marker;
    MarkerMeshes meshes;   // MakeMarkerMeshes(marker)
    std::int64_t received_ns;
    std::string where;
  };
  std::string topic_;
  MarkerSettings settings_;
  MarkerResources resources_;
  std::map<std::pair<std::string, int>, Kept> markers_;
  // the text markers' textures (each holding its glyph atlas) of the last Draw, kept until the next
  // one: text drawn frame after frame is then laid out once and uploaded to GL once, not per frame
  mutable std::mutex drawn_text_mutex_;
  mutable std::vector<std::shared_ptr<const texture::TextureImage>> drawn_text_;
};

}  // namespace urdfsnap::display
