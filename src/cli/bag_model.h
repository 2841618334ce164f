// MODEL given as a bag (`urdfsnap animate run.mcap -o run.mp4`): the robot description the bag
// recorded on /robot_description (or --description-topic), as RViz's RobotModel display takes it
// from the topic, written to a temporary URDF file for the model loader. Its package:// meshes are
// found as a file's are (--package, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH), and mesh file names
// relative to it from the bag's folder (cli/bag_scene.h).
#pragma once

#include <string>

namespace urdfsnap::cli {

class BagModel {
 public:
  // Reads the description (bag::ReadRobotDescription) into a new temporary folder (TMPDIR, else
  // /tmp). Throws urdfsnap::Error for a bag without one, or when the file cannot be written.
  BagModel(const std::string& bag, const std::string& topic);
  ~BagModel();
  BagModel(const BagModel&) = delete;
  BagModel& operator=(const BagModel&) = delete;

  // The temporary URDF file.
  const std::string& path() const { return path_; }
  // `message` naming the bag's topic where it names the temporary file, or a line of the
  // description by the bag's name ("run.mcap:11", from the meshes found beside the bag).
  std::string Located(std::string message) const;

 private:
  std::string bag_, folder_, path_, name_;  // name_: "run.mcap: '/robot_description'"
};

}  // namespace urdfsnap::cli
