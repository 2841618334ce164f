// One render described in the words of `urdfsnap render`: the same struct is filled from the
// command line (src/cli/render_command.cpp) and from a case of a snapshot suite
// (src/snapshot/suite_file.cpp), through one table of options, so both speak the same vocabulary.
#pragma once

#include <span>
#include <string>

#include "model/joint_values.h"
#include "request/model_request.h"

namespace urdfsnap::request {

// The image size when --size is not given: the RViz reference screenshots'.
inline constexpr const char* kDefaultSize = "640x480";

// View and display options as text, exactly as given; an empty string or false means "not given"
// (keep RViz's default or the .rviz file's value). RenderSession checks and applies them.
struct RenderRequest {
  ModelRequest model;
  std::string joint_file;    // YAML/JSON joint file, applied before `joints`
  model::NamedValues joints;  // NAME=VALUE in rad or m; a later entry wins
  std::string size;   // WxH; not given: kDefaultSize, or the calibration's size with --camera-info
  std::string rviz;
  std::string yaw, pitch, distance, focal, fov;
  std::string fixed_frame, background, alpha, tf_scale;
  std::string follow;   // the orbit view's Target Frame
  bool fit = false;
  std::string fit_margin;
  bool collision = false, no_visual = false, no_grid = false;
  bool tf = false, no_tf_names = false, no_tf_axes = false, no_tf_arrows = false;
  bool no_clamp = false, no_aa = false, allow_missing_meshes = false;
  // a calibrated camera instead of the orbit view (request/camera_parsing.h)
  std::string camera_info, camera_frame, camera_pose, near, far, underlay, underlay_alpha;
  bool distort = false;
};

// An option that takes a value: "--NAME VALUE" on the command line, "NAME: VALUE" in a suite.
struct TextOption {
  const char* name;
  const char* help;
  std::string RenderRequest::*field;
  bool is_path;  // a file name, resolved relative to the suite file
};

// An option that is on or off: "--NAME" on the command line, "NAME: true" in a suite.
struct FlagOption {
  const char* name;
  const char* help;
  bool RenderRequest::*field;
};

// Every view and display option of `render`, in --help order (the model, joints and xacro
// arguments have their own syntax on each side).
std::span<const TextOption> TextOptions();
std::span<const FlagOption> FlagOptions();

}  // namespace urdfsnap::request
