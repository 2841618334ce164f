// A calibrated camera's inputs from a recording, for `render --bag FILE --at T` and `animate
// FILE.mcap`: --underlay-topic's image behind the robot (in every frame, the image RViz's Camera
// display shows at the frame's moment: animation::FrameUnderlay) and --camera-info-topic's
// calibration (the latest sensor_msgs/CameraInfo whose header stamp, its log time when the
// publisher left the stamp at zero, is at or before the first moment drawn).
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "camera/camera_info.h"
#include "cli/bag_scene.h"
#include "common/warnings.h"
#include "request/render_request.h"
#include "request/resolved_request.h"

namespace urdfsnap::cli {

struct BagCameraOptions {
  std::string underlay_topic;      // --underlay-topic: the camera image behind the robot, "" for none
  std::string camera_info_topic;   // --camera-info-topic: the camera's calibration, "" for none

  // Adds --underlay-topic and --camera-info-topic to `command`; `moment` says which moment's
  // messages are taken ("--at", "each frame's moment").
  void AddOptions(CLI::App& command, const std::string& moment);
  // Throws urdfsnap::Error "OPTION: a topic of a recording; HOW" for a topic given without a bag.
  void RequireBag(bool bag, const std::string& how) const;
};

// The sensor_msgs/CameraInfo on `topic` at `time_ns`, checked as a --camera-info file is. Only the
// latest message's data is kept while reading. Throws urdfsnap::Error naming the bag for a topic
// it does not have or of another type, for no message at or before the moment, and naming the
// message for one that does not decode or a calibration that is not usable.
camera::CameraInfo ReadBagCameraInfo(const std::string& path, const std::string& topic, std::int64_t time_ns);

// `request` resolved with its files (request::ReadRequestFiles), its calibration
// --camera-info-topic's message at `moment_ns` when one is given (an error beside --camera-info).
request::ResolvedRequest ResolveWithBagCamera(const request::RenderRequest& request, const BagCameraOptions& options,
                                              const std::string& bag, std::int64_t moment_ns, Warnings& warnings);

// With --underlay-topic, sets `scene`'s underlay (prepared by PrepareBagScene for `bag`, whose
// trajectory time 0 is the stamp `stamp_at_zero`): the topic's images behind its calibrated camera.
// Throws urdfsnap::Error without a camera and beside --underlay (in `request`).
void AddBagUnderlay(const BagCameraOptions& options, const request::RenderRequest& request, const std::string& bag,
                    double stamp_at_zero, BagScene& scene);

}  // namespace urdfsnap::cli
