// What the Path and PoseArray displays share (path_display.cpp, pose_array_display.cpp): the last
// messages of their topic (Path's Buffer Length of them, PoseArray's one), each placed by TF at its
// header stamp when drawn. Subclasses draw the poses.
#pragma once

#include <deque>

#include "display/display.h"
#include "display/display_messages.h"

namespace urdfsnap::display {

class PoseListDisplay : public Display {
 public:
  const std::string& topic() const override { return topic_; }
  bool Reads(const std::string& type) const override;
  void Receive(const bag::MessageValue& message, std::int64_t time_ns, const std::string& where,
               Warnings& warnings) override;
  void Draw(std::int64_t time_ns, const FrameLookup& lookup, scene::Scene& scene,
            Warnings& warnings) const override;

  // Keeps `poses` received at `time_ns` (Receive's decoded message; the tests' entry).
  void Keep(PoseList poses, std::int64_t time_ns, const std::string& where, Warnings& warnings);

 protected:
  // `type`: the message type read; `keep`: how many messages are drawn.
  PoseListDisplay(std::string topic, std::string type, size_t keep);
  // Adds `poses` to `scene`; X_FH: their header frame in the fixed frame.
  virtual void DrawPoses(const PoseList& poses, const Eigen::Isometry3d& X_FH, scene::Scene& scene) const = 0;

 private:
  struct Kept {
    PoseList poses;
    std::int64_t received_ns;
    std::string where;
  };
  std::string topic_, type_;
  size_t keep_;
  std::deque<Kept> kept_;
};

}  // namespace urdfsnap::display
