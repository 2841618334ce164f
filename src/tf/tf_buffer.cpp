// TfBuffer: frames by index with a parent link each; lookups walk both frames up to their nearest
// common ancestor A and join the two chains there (X_TS = X_AT⁻¹ · X_AS), each dynamic transform
// found by binary search.
#include "tf/tf_buffer.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace urdfsnap::tf {
namespace {

bool Finite(const StampedTransform& t) {
  return t.translation.allFinite() && t.rotation.coeffs().allFinite();
}

std::string Quoted(const std::string& frame) { return "'" + frame + "'"; }

}  // namespace

int TfBuffer::IndexOf(const std::string& name) {
  const auto [entry, added] = index_.try_emplace(name, static_cast<int>(frames_.size()));
  if (added) {
    names_.push_back(name);
    frames_.emplace_back();
  }
  return entry->second;
}

void TfBuffer::Add(const StampedTransform& t, bool is_static, const std::string& where) {
  const std::string which = "transform " + Quoted(t.parent) + " -> " + Quoted(t.child);
  const auto fail = [&](const std::string& what) { throw Error(where + ": " + which + ": " + what); };
  if (t.parent.empty() || t.child.empty()) fail("a frame without a name");
  if (t.parent == t.child) fail("a frame that is its own parent");
  if (!Finite(t)) fail("a NaN or infinite value");
  if (std::abs(t.rotation.squaredNorm() - 1) >= kQuaternionTolerance) {
    fail("the quaternion (" + std::to_string(t.rotation.x()) + ", " +
         std::to_string(t.rotation.y()) + ", " + std::to_string(t.rotation.z()) + ", " +
         std::to_string(t.rotation.w()) + ") is not of unit length");
  }
  const int parent = IndexOf(t.parent);
  const int child = IndexOf(t.child);
  Frame& frame = frames_[child];
  if (frame.parent >= 0 && frame.parent != parent) {
    fail("frame " + Quoted(t.child) + " already has the parent " + Quoted(names_[frame.parent]) +
         "; a frame has one parent");
  }
  if (frame.parent < 0) {
    // a loop: the new parent descends from the child
    for (int up = parent; up >= 0; up = frames_[up].parent) {
      if (up == child) fail("a loop: " + Quoted(t.parent) + " descends from " + Quoted(t.child));
    }
    frame.parent = parent;
    frame.is_static = is_static;
  } else if (frame.is_static != is_static) {
    fail("frame " + Quoted(t.child) + " has both static and dynamic transforms");
  }
  const Sample sample{t.stamp_ns, t.translation, t.rotation.normalized()};
  if (is_static) {
    frame.samples.assign(1, sample);  // the latest static transform holds
    return;
  }
  if (!frame.samples.empty()) {
    const std::int64_t last = frame.samples.back().stamp_ns;
    if (t.stamp_ns == last) return;  // repeated data
    if (t.stamp_ns < last) {
      fail("stamped " + std::to_string(t.stamp_ns) + " ns, before the frame's previous stamp " +
           std::to_string(last) + " ns: stamps go backwards");
    }
  }
  frame.samples.push_back(sample);
}

Eigen::Isometry3d TfBuffer::Transform(const Frame& frame, std::int64_t time_ns,
                                      bool& extrapolated) const {
  const std::vector<Sample>& samples = frame.samples;
  const auto pose = [](const Eigen::Vector3d& translation, const Eigen::Quaterniond& rotation) {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = rotation.toRotationMatrix();
    X.translation() = translation;
    return X;
  };
  if (frame.is_static || samples.size() == 1) {
    extrapolated = extrapolated || (!frame.is_static && time_ns != samples.front().stamp_ns);
    return pose(samples.front().translation, samples.front().rotation);
  }
  const auto after = std::lower_bound(
      samples.begin(), samples.end(), time_ns,
      [](const Sample& sample, std::int64_t t) { return sample.stamp_ns < t; });
  if (after == samples.begin() || after == samples.end()) {
    const Sample& nearest = after == samples.end() ? samples.back() : samples.front();
    extrapolated = extrapolated || nearest.stamp_ns != time_ns;
    return pose(nearest.translation, nearest.rotation);
  }
  const Sample& before = *(after - 1);
  // tf2's interpolate (cache.cpp): lerp of the translation, slerp of the rotation
  const double ratio = static_cast<double>(time_ns - before.stamp_ns) /
                       static_cast<double>(after->stamp_ns - before.stamp_ns);
  return pose(before.translation + ratio * (after->translation - before.translation),
              before.rotation.slerp(ratio, after->rotation));
}

Eigen::Isometry3d TfBuffer::ToAncestor(int index, int ancestor, std::int64_t time_ns,
                                       bool& extrapolated) const {
  Eigen::Isometry3d X_AF = Eigen::Isometry3d::Identity();
  for (int frame = index; frame != ancestor; frame = frames_[frame].parent) {
    X_AF = Transform(frames_[frame], time_ns, extrapolated) * X_AF;
  }
  return X_AF;
}

std::optional<Lookup> TfBuffer::Find(const std::string& target, const std::string& source,
                                     std::int64_t time_ns) const {
  const auto target_index = index_.find(target);
  const auto source_index = index_.find(source);
  if (target_index == index_.end() || source_index == index_.end()) return std::nullopt;
  // the nearest common ancestor, as tf2's walkToTopParent finds it: transforms above it (a moving
  // base above two of its links) are not needed, nor their extrapolation
  std::vector<int> source_chain;
  for (int frame = source_index->second; frame >= 0; frame = frames_[frame].parent) {
    source_chain.push_back(frame);
  }
  int ancestor = target_index->second;
  while (ancestor >= 0 &&
         std::find(source_chain.begin(), source_chain.end(), ancestor) == source_chain.end()) {
    ancestor = frames_[ancestor].parent;
  }
  if (ancestor < 0) return std::nullopt;  // different trees
  Lookup lookup;
  const Eigen::Isometry3d X_AT = ToAncestor(target_index->second, ancestor, time_ns, lookup.extrapolated);
  const Eigen::Isometry3d X_AS = ToAncestor(source_index->second, ancestor, time_ns, lookup.extrapolated);
  lookup.X_TS = X_AT.inverse() * X_AS;
  return lookup;
}

std::string TfBuffer::ParentOf(const std::string& frame) const {
  const auto index = index_.find(frame);
  if (index == index_.end() || frames_[index->second].parent < 0) return "";
  return names_[frames_[index->second].parent];
}

}  // namespace urdfsnap::tf
