// The camera a golden was drawn with, stored beside it as NAME.camera.json (robot.png →
// robot.camera.json), so that a check draws with the same camera even when `fit: true` would now
// frame an edited model differently: a change to one link then changes that link's pixels only,
// and the move of the camera is reported on its own. Orbit views only: a case seen through a
// calibrated camera (camera-info) is fully given by its files and stores none.
//
// The file: {"format": "urdfsnap-golden-camera", "yaw": rad, "pitch": rad, "distance": m,
// "focal": [x, y, z] m, "fov_y": rad, "near_clip": m, "eye": [x, y, z] m, "up": [x, y, z]};
// eye and up are for people (they follow from the rest and are not read back).
#pragma once

#include <optional>
#include <string>

#include "scene/orbit_view.h"

namespace urdfsnap::snapshot {

// "goldens/robot.camera.json" for "goldens/robot.png".
std::string GoldenCameraFile(const std::string& golden);

// The file's text for `view`, numbers exact (they read back to the same doubles).
std::string GoldenCameraJson(const scene::OrbitView& view);

// The camera stored in `path`; nullopt when there is no such file (a golden made before cameras
// were stored). Throws urdfsnap::Error naming the file for one that cannot be read or is malformed.
std::optional<scene::OrbitView> ReadGoldenCamera(const std::string& path);

// "" when `now` draws as `stored` (within 1e-9 of the distance); else one line for people saying
// how the camera moved: "camera moved: the eye by 4.2 cm, the focal point by 3.1 cm (distance
// 1.2345 m → 1.2 m)".
std::string CameraMovement(const scene::OrbitView& stored, const scene::OrbitView& now);

}  // namespace urdfsnap::snapshot
