// ReadCameraFiles and ParseCameraSettings: camera options to a camera::CameraModel, a pose and an
// underlay image.
#include "request/camera_parsing.h"

#include <algorithm>

#include "camera/camera_info.h"
#include "common/error.h"
#include "common/number_text.h"
#include "image/png_reader.h"
#include "request/value_parsing.h"

namespace urdfsnap::request {

namespace {

// "X,Y,Z,QX,QY,QZ,QW" → pose; the quaternion is normalised, as tf2 does.
Eigen::Isometry3d ParsePose(const std::string& text, const std::string& option) {
  // seven numbers between six commas, read by the one number grammar
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  double n[7];
  if (std::count(text.begin(), text.end(), ',') != 6 || text.find_first_of(" \t") != std::string::npos ||
      text.find(",,") != std::string::npos || !ParseNumbers(spaced, 7, n)) {
    throw Error(option + " '" + text + "': expected seven finite numbers X,Y,Z,QX,QY,QZ,QW");
  }
  const Eigen::Quaterniond q(n[6], n[3], n[4], n[5]);
  if (q.norm() < 1e-9) throw Error(option + " '" + text + "': the quaternion QX,QY,QZ,QW is zero");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(n[0], n[1], n[2]);
  pose.linear() = q.normalized().toRotationMatrix();
  return pose;
}

}  // namespace

CameraFiles ReadCameraFiles(const RenderRequest& r) {
  CameraFiles files;
  // without a camera an underlay is an error of the options (ParseCameraSettings), not a file to read
  if (r.camera_info.empty() && r.camera_frame.empty() && r.camera_pose.empty()) return files;
  if (!r.camera_info.empty()) files.info = camera::ReadCameraInfo(r.camera_info);
  if (!r.underlay.empty()) files.underlay = std::make_shared<const image::Image>(image::ReadPng(r.underlay));
  return files;
}

std::optional<render::CameraSettings> ParseCameraSettings(const RenderRequest& r, const CameraFiles& files,
                                                          const OptionLabel& label, render::RenderSettings& settings) {
  // a calibration may come from elsewhere than --camera-info's file (render --bag's topic)
  if (!files.info && r.camera_frame.empty() && r.camera_pose.empty()) {
    for (const auto& [given, name] : {std::pair{!r.near.empty(), "near"}, {!r.far.empty(), "far"},
                                      {r.distort, "distort"}, {!r.underlay.empty(), "underlay"},
                                      {!r.underlay_alpha.empty(), "underlay-alpha"}}) {
      if (given) {
        throw Error(label(name) + " needs a camera: " + label("camera-info") + ", " + label("camera-frame") +
                    " or " + label("camera-pose"));
      }
    }
    return std::nullopt;
  }
  if (r.distort && !files.info) {
    throw Error(label("distort") + " needs " + label("camera-info") + " (the lens's distortion coefficients)");
  }
  camera::Clipping clipping;
  if (!r.near.empty()) clipping.near = ParseInRange(r.near, label("near"), 1e-6, 1e6);
  if (!r.far.empty()) clipping.far = ParseInRange(r.far, label("far"), 1e-6, 1e9);
  if (!(clipping.far > clipping.near)) {
    throw Error(label("far") + " " + FormatNumber(clipping.far) + " must be beyond " + label("near") + " " +
                FormatNumber(clipping.near));
  }

  render::CameraSettings camera;
  if (files.info) {
    camera.model = std::make_shared<const camera::CameraModel>(*files.info, r.distort, clipping);
    settings.size = {files.info->width, files.info->height};
  } else {
    camera.model = std::make_shared<const camera::CameraModel>(settings.view.fov_y, settings.size.width,
                                                               settings.size.height, clipping);
  }
  camera.frame = r.camera_frame;
  if (!r.camera_pose.empty()) camera.pose = ParsePose(r.camera_pose, label("camera-pose"));
  if (files.underlay) {
    camera.underlay = files.underlay;
    camera.underlay_file = r.underlay;
  }
  if (!r.underlay_alpha.empty()) camera.overlay_alpha = ParseInRange(r.underlay_alpha, label("underlay-alpha"), 0, 1);
  // after the values, so that a bad number is named first
  if (r.fit) {
    throw Error(label("fit") + " frames the orbit view; a camera (" + label("camera-info") + ", " +
                label("camera-frame") + ", " + label("camera-pose") + ") is placed as given");
  }
  return camera;
}

}  // namespace urdfsnap::request
