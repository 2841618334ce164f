// A request with its text resolved into types: the model to load, the render settings (the .rviz
// file and the options applied, --fit not yet done: that needs the robot), and the joint values
// given (the joint file's, then -j's). Resolving reads the request's own files (.rviz, joint file,
// camera info, underlay) once; RequestFiles keeps them so that many requests over the same files (the live view's
// queries) read none.
#pragma once

#include <string>

#include "common/warnings.h"
#include "model/joint_values.h"
#include "render/render_settings.h"
#include "request/camera_parsing.h"
#include "request/model_request.h"
#include "request/render_request.h"
#include "request/settings_parsing.h"

namespace urdfsnap::request {

struct ResolvedRequest {
  ModelRequest model;
  render::RenderSettings settings;  // settings.fit says how to frame the robot, not yet applied
  model::NamedValues joints;        // the joint file's values, then -j's; a later entry wins
  bool clamp = true;                // joint values beyond a joint's limits are clamped (not --no-clamp)
  std::string rviz;                 // the .rviz file the settings came from, for its warnings
  bool fixed_frame_given = false;   // --fixed-frame was given (an .rviz frame is only a default)
  bool target_frame_given = false;  // --follow was given (likewise)
};

// What a request's files say, read once.
struct RequestFiles {
  render::RenderSettings base;   // RViz's defaults with the .rviz file applied
  model::NamedValues joint_file; // the joint file's values (none without a joint file)
  CameraFiles camera;            // --camera-info's calibration, --underlay's image
};

// Reads the request's .rviz, joint, camera info and underlay files. Throws urdfsnap::Error for an
// unreadable or bad one.
RequestFiles ReadRequestFiles(const RenderRequest& request, Warnings& warnings);

// The joint values a request gives: the joint file's (`joint_file`), then -j's, in that order so
// that -j wins over the file.
model::NamedValues GivenJoints(const model::NamedValues& joint_file, const RenderRequest& request);

// `request` resolved over `files` (which must be ReadRequestFiles of a request naming the same
// .rviz and joint files); reads no file. Throws urdfsnap::Error for a bad option value, named
// through `label`.
ResolvedRequest ResolveRequest(const RenderRequest& request, const RequestFiles& files, const OptionLabel& label);

// ReadRequestFiles, then ResolveRequest.
ResolvedRequest ResolveRequest(const RenderRequest& request, const OptionLabel& label, Warnings& warnings);

}  // namespace urdfsnap::request
