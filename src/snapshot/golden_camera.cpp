// Golden cameras as small JSON files through nlohmann_json (the results files' library).
#include "snapshot/golden_camera.h"

#include <cmath>
#include <filesystem>
#include <numbers>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/json_text.h"
#include "common/number_text.h"

namespace urdfsnap::snapshot {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kFormat = "urdfsnap-golden-camera";

Json VectorJson(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

double Number(const Json& file, const char* key, const std::string& path) {
  if (!file.contains(key) || !file[key].is_number() || !std::isfinite(file[key].get<double>())) {
    throw Error(path + ": '" + key + "' must be a finite number");
  }
  return file[key].get<double>();
}

// A length for people: cm under a metre, else m.
std::string Length(double metres) {
  return std::abs(metres) < 1 ? FormatForPeople(metres * 100, "cm") : FormatForPeople(metres, "m");
}

}  // namespace

std::string GoldenCameraFile(const std::string& golden) {
  return std::filesystem::path(golden).replace_extension(".camera.json").string();
}

std::string GoldenCameraJson(const scene::OrbitView& view) {
  const Eigen::Matrix4d V = scene::ViewMatrix(view);
  const Json file = {{"format", kFormat},
                     {"yaw", view.yaw},
                     {"pitch", view.pitch},
                     {"distance", view.distance},
                     {"focal", VectorJson(view.focal)},
                     {"fov_y", view.fov_y},
                     {"near_clip", view.near_clip},
                     {"eye", VectorJson(scene::EyePosition(view))},
                     {"up", VectorJson(V.block<1, 3>(1, 0).transpose())}};
  return file.dump(2) + "\n";
}

std::optional<scene::OrbitView> ReadGoldenCamera(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  std::string text;
  try {
    text = ReadFileBounded(path, 1 << 16);
  } catch (const FileReadError& e) {
    throw Error(path + ": " + e.what());
  }
  const Json file = ParseJson(text, path);
  if (!file.is_object() || !file.contains("format") || file["format"] != kFormat) {
    throw Error(path + ": not a golden camera file (expected \"format\": \"" + kFormat + "\")");
  }
  scene::OrbitView view;
  view.yaw = Number(file, "yaw", path);
  view.pitch = Number(file, "pitch", path);
  view.distance = Number(file, "distance", path);
  view.fov_y = Number(file, "fov_y", path);
  view.near_clip = Number(file, "near_clip", path);
  const Json& focal = file.contains("focal") ? file["focal"] : Json();
  if (!focal.is_array() || focal.size() != 3 ||
      !std::all_of(focal.begin(), focal.end(), [](const Json& v) { return v.is_number(); })) {
    throw Error(path + ": 'focal' must be three numbers [x, y, z]");
  }
  view.focal = {focal[0].get<double>(), focal[1].get<double>(), focal[2].get<double>()};
  if (!view.focal.allFinite() || view.distance <= 0 || view.fov_y <= 0 || view.fov_y >= std::numbers::pi ||
      view.near_clip <= 0) {
    throw Error(path + ": the camera is not one urdfsnap draws (distance, fov_y and near_clip must be positive)");
  }
  return view;
}

std::string CameraMovement(const scene::OrbitView& stored, const scene::OrbitView& now) {
  const double eye = (scene::EyePosition(now) - scene::EyePosition(stored)).norm();
  const double focal = (now.focal - stored.focal).norm();
  const double tolerance = 1e-9 * std::max(1.0, stored.distance);
  const bool turned = std::abs(now.yaw - stored.yaw) > 1e-12 || std::abs(now.pitch - stored.pitch) > 1e-12 ||
                      std::abs(now.fov_y - stored.fov_y) > 1e-12;
  if (eye <= tolerance && focal <= tolerance && !turned) return "";
  std::string text = "camera moved: the eye by " + Length(eye) + ", the focal point by " + Length(focal) +
                     " (distance " + FormatForPeople(stored.distance) + " m → " + FormatForPeople(now.distance, "m");
  if (turned) {
    const double degrees = 180 / std::numbers::pi;
    text += "; yaw " + FormatForPeople(stored.yaw * degrees) + "° → " + FormatForPeople(now.yaw * degrees) +
            "°, pitch " + FormatForPeople(stored.pitch * degrees) + "° → " + FormatForPeople(now.pitch * degrees) +
            "°, field of view " + FormatForPeople(stored.fov_y * degrees) + "° → " +
            FormatForPeople(now.fov_y * degrees) + "°";
  }
  return text + ")";
}

}  // namespace urdfsnap::snapshot
