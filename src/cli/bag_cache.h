// cli::BagCache: what one still of a bag (`render --bag`, serve's time slider) keeps for the next,
// and the two reads it saves, each done once: the bag's joint states and its TF.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "animation/frame_displays.h"
#include "common/warnings.h"
#include "display/display_settings.h"
#include "motion/trajectory.h"
#include "tf/tf_buffer.h"

namespace urdfsnap::cli {

// What one still of a bag keeps for the next (serve's time slider), so that a request does not
// read the bag again: its joint states and TF as read once (what a recording's animation keeps
// too), and the message displays, reused while the same displays in the same fixed frame are asked
// for at the same or a later moment, so that a slider dragged forward reads only the messages
// between two moments; an earlier moment or other displays start them again from the bag's
// beginning. Never the bag's other messages.
struct BagCache {
  std::optional<motion::Trajectory> trajectory;   // the joint states of `trajectory_topic`
  std::string trajectory_topic;
  std::shared_ptr<const tf::TfBuffer> transforms;   // the bag's /tf and /tf_static, once read
  std::vector<display::DisplaySettings> settings;   // what `displays` were made for
  std::string fixed_frame;
  double stamp_at_zero = 0;
  std::shared_ptr<animation::FrameDisplays> displays;
};

// The joint states on `topic` of `bag`: `cache`'s when it read that topic, else read (and kept in
// `cache` when one is given). Throws as motion::ReadTrajectory does.
motion::Trajectory BagJointStates(const std::string& bag, const std::string& topic, Warnings& warnings,
                                  BagCache* cache);

// The bag's TF: `cache`'s when it has read it, else read (and kept in `cache` when one is given).
// Throws as tf::ReadBagTransforms does.
std::shared_ptr<const tf::TfBuffer> BagTransforms(const std::string& bag, BagCache* cache);

}  // namespace urdfsnap::cli
