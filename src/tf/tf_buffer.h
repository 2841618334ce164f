// The transform tree of a recording, kept as tf2's BufferCore keeps it: per child frame its one
// parent and either a static transform (the latest given wins) or a time-ordered list of dynamic
// ones, looked up at any time by interpolating between the two samples around it (translation
// linearly, rotation by slerp). Unlike tf2, which logs and drops them, transforms that would make
// the tree wrong (a NaN, a quaternion that is not unit length, a second parent, a loop, a stamp
// before the child's previous one) are errors: urdfsnap replays a finished recording, where such
// data is a broken bag rather than a passing glitch.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

namespace urdfsnap::tf {

// tf2's QUATERNION_NORMALIZATION_TOLERANCE (buffer_core.cpp): |x²+y²+z²+w² - 1| must be below it.
inline constexpr double kQuaternionTolerance = 10e-3;

// One transform as a TransformStamped carries it: the child frame's pose in its parent's.
struct StampedTransform {
  std::string parent;  // header.frame_id
  std::string child;   // child_frame_id
  std::int64_t stamp_ns = 0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();        // metres
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // x, y, z, w as recorded
};

// What a lookup found.
struct Lookup {
  Eigen::Isometry3d X_TS = Eigen::Isometry3d::Identity();  // the source frame in the target frame
  // the time was outside a dynamic transform's samples on the way: its nearest sample was used,
  // as a player shows the last state it had (tf2 would throw an ExtrapolationException)
  bool extrapolated = false;
};

class TfBuffer {
 public:
  // Adds a transform; `where` says where it came from ("run.mcap: message 3 on '/tf'") for the
  // errors, which are urdfsnap::Error "WHERE: ...": an empty or equal parent and child name, a NaN
  // or infinite value, a quaternion whose squared length is not within kQuaternionTolerance of 1,
  // a child that already has another parent, a parent that descends from the child (a loop), a
  // dynamic stamp before the child's last one, or a frame given both static and dynamic
  // transforms. A dynamic transform repeating the child's last stamp is skipped, as tf2 skips it.
  void Add(const StampedTransform& transform, bool is_static, const std::string& where);

  // The pose of frame `source` in frame `target` at `time_ns`: both frames are walked up to their
  // nearest common ancestor, each dynamic transform on the way interpolated at that time. Nothing
  // when a frame is unknown or the two are in different trees.
  std::optional<Lookup> Find(const std::string& target, const std::string& source,
                             std::int64_t time_ns) const;

  // Every frame, parents and children, in the order they were first named.
  const std::vector<std::string>& frames() const { return names_; }
  // The parent of `frame`, or "" for a root or an unknown frame.
  std::string ParentOf(const std::string& frame) const;

 private:
  struct Sample {
    std::int64_t stamp_ns;
    Eigen::Vector3d translation;
    Eigen::Quaterniond rotation;
  };
  struct Frame {
    int parent = -1;
    bool is_static = false;
    std::vector<Sample> samples;  // static: one; dynamic: by increasing stamp
  };

  int IndexOf(const std::string& name);
  // X_PC of `frame` at `time_ns`; sets `extrapolated` when the time is outside its samples.
  Eigen::Isometry3d Transform(const Frame& frame, std::int64_t time_ns, bool& extrapolated) const;
  // The pose of frame `index` in the frame of `ancestor`, one of its ancestors (or itself).
  Eigen::Isometry3d ToAncestor(int index, int ancestor, std::int64_t time_ns,
                               bool& extrapolated) const;

  std::unordered_map<std::string, int> index_;
  std::vector<std::string> names_;
  std::vector<Frame> frames_;
};

}  // namespace urdfsnap::tf
