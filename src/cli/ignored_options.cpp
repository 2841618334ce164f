// Warnings for command options given where they do nothing, compared with their defaults.
#include "cli/ignored_options.h"

#include "bag/joint_state_bag.h"
#include "bag/recorded_description.h"

namespace urdfsnap::cli {

void WarnOfUnusedBagTopics(const std::string& topic, const std::string& description_topic, bool reads_bag,
                           bool model_from_bag, const std::string& bag_option, Warnings& warnings) {
  if (!reads_bag && topic != bag::kDefaultJointStateTopic) {
    WarnIgnored(warnings, "--topic " + topic, "it names the joint states of a bag, and there is no " + bag_option);
  }
  if (!model_from_bag && description_topic != bag::kDefaultDescriptionTopic) {
    WarnIgnored(warnings, "--description-topic " + description_topic,
                "it names a bag's recorded robot description, and MODEL gives the robot");
  }
}

void WarnOfUnusedMaskDilate(int mask_dilate, const std::string& mask, Warnings& warnings) {
  if (mask_dilate != 0 && mask.empty()) {
    WarnIgnored(warnings, "--mask-dilate " + std::to_string(mask_dilate), "it grows --mask, and --mask is not given");
  }
}

}  // namespace urdfsnap::cli
