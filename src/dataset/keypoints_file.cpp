// KeypointsJson with nlohmann_json, keys in the documented order.
#include "dataset/keypoints_file.h"

#include "dataset/camera_json.h"

namespace urdfsnap::dataset {

std::string KeypointsJson(const camera::CameraModel& camera, const Eigen::Isometry3d& X_FC,
                          const std::vector<FrameKeypoint>& keypoints, int indent) {
  nlohmann::ordered_json json;
  json["camera"] = CameraJson(camera, X_FC);
  json["frames"] = nlohmann::ordered_json::array();
  for (const FrameKeypoint& k : keypoints) {
    nlohmann::ordered_json frame;
    frame["name"] = k.name;
    frame["kind"] = k.kind == FrameKeypoint::Kind::kLink ? "link" : "joint";
    frame["u"] = k.uv ? nlohmann::ordered_json(k.uv->x()) : nlohmann::ordered_json(nullptr);
    frame["v"] = k.uv ? nlohmann::ordered_json(k.uv->y()) : nlohmann::ordered_json(nullptr);
    frame["depth"] = k.depth;
    frame["in_image"] = k.in_image;
    frame["visible"] = k.visible;
    json["frames"].push_back(std::move(frame));
  }
  return json.dump(indent) + "\n";
}

}  // namespace urdfsnap::dataset
