// Field-by-field decoding of the display messages from bag::MessageValue trees.
#include "display/display_messages.h"

namespace urdfsnap::display {
namespace {

std::int64_t Nanoseconds(const bag::MessageValue& time) {
  return static_cast<std::int64_t>(time["sec"].number) * 1'000'000'000 +
         static_cast<std::int64_t>(time["nanosec"].number);
}

Header DecodeHeader(const bag::MessageValue& value) {
  std::string frame = value["frame_id"].text;
  if (!frame.empty() && frame.front() == '/') frame.erase(0, 1);   // tf2 drops a leading slash
  return {frame, Nanoseconds(value["stamp"])};
}

Eigen::Vector3d Vector(const bag::MessageValue& value) {
  return {value["x"].number, value["y"].number, value["z"].number};
}

Eigen::Vector4f Colour(const bag::MessageValue& value) {
  return Eigen::Vector4d(value["r"].number, value["g"].number, value["b"].number, value["a"].number)
      .cast<float>();
}

Pose DecodePose(const bag::MessageValue& value) {
  const bag::MessageValue& q = value["orientation"];
  return {Vector(value["position"]),
          Eigen::Quaterniond(q["w"].number, q["x"].number, q["y"].number, q["z"].number)};
}

}  // namespace

Marker DecodeMarker(const bag::MessageValue& value) {
  Marker m;
  m.header = DecodeHeader(value["header"]);
  m.ns = value["ns"].text;
  m.id = static_cast<int>(value["id"].number);
  m.type = static_cast<int>(value["type"].number);
  m.action = static_cast<int>(value["action"].number);
  m.pose = DecodePose(value["pose"]);
  m.scale = Vector(value["scale"]);
  m.colour = Colour(value["color"]);
  m.lifetime_ns = Nanoseconds(value["lifetime"]);
  m.frame_locked = value["frame_locked"].number != 0;
  const auto& points = value["points"].items;
  m.points.reserve(points.size());
  for (const bag::MessageValue& p : points) m.points.push_back(Vector(p).cast<float>());
  const auto& colours = value["colors"].items;
  m.colours.reserve(colours.size());
  for (const bag::MessageValue& c : colours) m.colours.push_back(Colour(c));
  m.text = value["text"].text;
  m.mesh_resource = value["mesh_resource"].text;
  m.mesh_use_embedded_materials = value["mesh_use_embedded_materials"].number != 0;
  return m;
}

std::vector<Marker> DecodeMarkerArray(const bag::MessageValue& value) {
  std::vector<Marker> markers;
  for (const bag::MessageValue& m : value["markers"].items) markers.push_back(DecodeMarker(m));
  return markers;
}

PoseList DecodePath(const bag::MessageValue& value) {
  PoseList path{DecodeHeader(value["header"]), {}};
  for (const bag::MessageValue& p : value["poses"].items) path.poses.push_back(DecodePose(p["pose"]));
  return path;
}

PoseList DecodePoseArray(const bag::MessageValue& value) {
  PoseList poses{DecodeHeader(value["header"]), {}};
  for (const bag::MessageValue& p : value["poses"].items) poses.poses.push_back(DecodePose(p));
  return poses;
}

}  // namespace urdfsnap::display
