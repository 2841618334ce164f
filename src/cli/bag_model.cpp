// BagModel: mkdtemp, the description written whole, the folder removed with everything in it.
#include "cli/bag_model.h"

#include <stdlib.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "bag/recorded_description.h"
#include "common/error.h"

namespace urdfsnap::cli {

BagModel::BagModel(const std::string& bag, const std::string& topic)
    : bag_(bag), name_(bag + ": '" + topic + "'") {
  const std::string description = bag::ReadRobotDescription(bag, topic);
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/urdfsnap-description-XXXXXX";
  if (!mkdtemp(pattern.data())) {
    throw Error(name_ + ": cannot make a temporary folder for the description: " +
                std::strerror(errno));
  }
  folder_ = pattern;
  path_ = folder_ + "/robot_description.urdf";
  std::ofstream out(path_, std::ios::binary);
  out << description;
  if (!out.flush()) {
    std::filesystem::remove_all(folder_);
    throw Error(name_ + ": cannot write the description to " + path_);
  }
}

BagModel::~BagModel() {
  std::error_code ignored;
  std::filesystem::remove_all(folder_, ignored);
}

std::string BagModel::Located(std::string message) const {
  for (std::size_t at; (at = message.find(path_)) != std::string::npos;) {
    message.replace(at, path_.size(), name_);
  }
  // a line of the description named after the bag, whose folder its meshes are found from
  const std::string line_of_bag = bag_ + ":";
  for (std::size_t at = 0; (at = message.find(line_of_bag, at)) != std::string::npos;) {
    const std::size_t after = at + line_of_bag.size();
    if (after < message.size() && std::isdigit(static_cast<unsigned char>(message[after]))) {
      message.replace(at, bag_.size(), name_);
      at += name_.size();
    } else {
      at = after;
    }
  }
  return message;
}

}  // namespace urdfsnap::cli
