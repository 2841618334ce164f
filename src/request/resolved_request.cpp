// ResolveRequest: the request's files read once, its option texts applied over them.
#include "request/resolved_request.h"

namespace urdfsnap::request {

RequestFiles ReadRequestFiles(const RenderRequest& r, Warnings& warnings) {
  RequestFiles files;
  files.base = ReadBaseSettings(r, warnings);
  if (!r.joint_file.empty()) files.joint_file = model::ReadJointFile(r.joint_file);
  files.camera = ReadCameraFiles(r);
  return files;
}

model::NamedValues GivenJoints(const model::NamedValues& joint_file, const RenderRequest& r) {
  model::NamedValues given = joint_file;
  given.insert(given.end(), r.joints.begin(), r.joints.end());
  return given;
}

ResolvedRequest ResolveRequest(const RenderRequest& r, const RequestFiles& files, const OptionLabel& label) {
  ResolvedRequest resolved;
  resolved.model = r.model;
  resolved.settings = files.base;
  ApplyOptions(r, files.camera, label, resolved.settings);
  resolved.joints = GivenJoints(files.joint_file, r);
  resolved.clamp = !r.no_clamp;
  resolved.rviz = r.rviz;
  resolved.fixed_frame_given = !r.fixed_frame.empty();
  resolved.target_frame_given = !r.follow.empty();
  return resolved;
}

ResolvedRequest ResolveRequest(const RenderRequest& r, const OptionLabel& label, Warnings& warnings) {
  ResolvedRequest resolved = ResolveRequest(r, ReadRequestFiles(r, warnings), label);
  WarnOfOptionsWithoutEffect(r, label, warnings);   // once the values are known to be good
  return resolved;
}

}  // namespace urdfsnap::request
