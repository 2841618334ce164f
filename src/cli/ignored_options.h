// The command options (beside the render request's, which request::WarnOfOptionsWithoutEffect
// checks) that do nothing with the others given: one warning each, worded by WarnIgnored.
#pragma once

#include <string>

#include "common/warnings.h"

namespace urdfsnap::cli {

// --topic without a bag to read joint states from (`bag_option`: the option that gives one), and
// --description-topic when the robot does not come from a bag.
void WarnOfUnusedBagTopics(const std::string& topic, const std::string& description_topic, bool reads_bag,
                           bool model_from_bag, const std::string& bag_option, Warnings& warnings);

// --mask-dilate without --mask.
void WarnOfUnusedMaskDilate(int mask_dilate, const std::string& mask, Warnings& warnings);

}  // namespace urdfsnap::cli
