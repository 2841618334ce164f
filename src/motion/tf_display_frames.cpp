// TfDisplayFrames: the links first, then TF's other frames, each found from a link (the nearest
// above it, else the first link TF names); per frame one TfBuffer lookup from that link.
#include "motion/tf_display_frames.h"

#include <algorithm>
#include <cmath>


namespace urdfsnap::motion {

TfDisplayFrames::TfDisplayFrames(const model::Robot& robot, std::shared_ptr<const tf::TfBuffer> buffer,
                                 double stamp_at_zero, std::string bag)
    : buffer_(std::move(buffer)), stamp_at_zero_(stamp_at_zero), bag_(std::move(bag)),
      link_count_(robot.links().size()), names_(robot.LinkNames()), parents_(robot.ParentLinks()) {
  const std::vector<std::string>& tf_frames = buffer_->frames();
  // frames above the robot (odom, map) are found from the first link TF names
  const auto in_tf = [&](const std::string& frame) {
    return std::find(tf_frames.begin(), tf_frames.end(), frame) != tf_frames.end();
  };
  int top_anchor = -1;
  for (std::size_t link = 0; link < link_count_ && top_anchor < 0; ++link) {
    if (in_tf(names_[link])) top_anchor = static_cast<int>(link);
  }
  for (const std::string& frame : tf_frames) {
    if (robot.FindLink(frame) >= 0) continue;
    // a frame below a link (a sensor's) from that link, which TF may not connect to the others
    int anchor = -1;
    for (std::string up = buffer_->ParentOf(frame); !up.empty() && anchor < 0; up = buffer_->ParentOf(up)) {
      anchor = robot.FindLink(up);
    }
    if (anchor < 0 && top_anchor >= 0 && buffer_->Find(names_[top_anchor], frame, 0)) anchor = top_anchor;
    if (anchor < 0) continue;
    names_.push_back(frame);
    anchors_.push_back(anchor);
  }
  // the TF parents of the frames without a robot parent: the root's odom, a sensor's link
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (i < link_count_ && parents_[i] >= 0) continue;
    const auto parent = std::find(names_.begin(), names_.end(), buffer_->ParentOf(names_[i]));
    if (i >= link_count_) parents_.push_back(-1);
    if (parent != names_.end()) parents_[i] = static_cast<int>(parent - names_.begin());
  }
}

std::vector<Eigen::Isometry3d> TfDisplayFrames::Poses(const std::vector<Eigen::Isometry3d>& X_SL, double t,
                                                      Warnings& warnings) const {
  std::vector<Eigen::Isometry3d> X_ST(X_SL.begin(), X_SL.end());
  const auto time_ns = static_cast<std::int64_t>(std::llround((stamp_at_zero_ + t) * 1e9));
  bool extrapolated = false;
  for (std::size_t i = link_count_; i < names_.size(); ++i) {
    const int anchor = anchors_[i - link_count_];
    const tf::Lookup lookup = *buffer_->Find(names_[anchor], names_[i], time_ns);
    extrapolated = extrapolated || lookup.extrapolated;
    X_ST.push_back(X_SL[anchor] * lookup.X_TS);
  }
  if (extrapolated) {
    warnings.Add(bag_ + ": the TF display's frames are not all recorded at some frames' times (before "
                 "their first or after their last transform); those frames hold the nearest one");
  }
  return X_ST;
}

}  // namespace urdfsnap::motion
