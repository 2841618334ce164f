// BagJointStates and BagTransforms: read once, then kept in the cache.
#include "cli/bag_cache.h"

#include "motion/trajectory_file.h"
#include "tf/bag_transforms.h"

namespace urdfsnap::cli {

motion::Trajectory BagJointStates(const std::string& bag, const std::string& topic, Warnings& warnings,
                                  BagCache* cache) {
  if (cache && cache->trajectory && cache->trajectory_topic == topic) return *cache->trajectory;
  motion::Trajectory read = motion::ReadTrajectory(bag, {topic}, warnings);
  if (cache) {
    cache->trajectory = read;
    cache->trajectory_topic = topic;
  }
  return read;
}

std::shared_ptr<const tf::TfBuffer> BagTransforms(const std::string& bag, BagCache* cache) {
  if (cache && cache->transforms) return cache->transforms;
  auto transforms = std::make_shared<const tf::TfBuffer>(tf::ReadBagTransforms(bag));
  if (cache) cache->transforms = transforms;
  return transforms;
}

}  // namespace urdfsnap::cli
