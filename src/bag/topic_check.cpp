// Matches and RequireTopic: the topic's short type name against the required ones.
#include "bag/topic_check.h"

#include <algorithm>

#include "common/error.h"

namespace urdfsnap::bag {

bool Matches(const TopicRequirement& r, const BagTopic& t, const std::string& path) {
  if (t.name != r.topic) return false;
  if (std::find(r.types.begin(), r.types.end(), ShortTypeName(t.type)) == r.types.end() || t.encoding != "cdr") {
    throw Error(path + ": " + r.option + " '" + r.topic + "' carries '" + t.type + "' messages encoded as '" +
                t.encoding + "'; urdfsnap reads " + r.what + " in 'cdr' (ROS 2)");
  }
  return true;
}

void RequireTopic(const TopicRequirement& r, const std::string& path) {
  bool found = false;
  ReadBagMessages(path, [&](const BagTopic& t) { found = found || Matches(r, t, path); return false; },
                  [](const BagMessage&) {});
  if (!found) throw Error(path + ": no topic '" + r.topic + "' (" + r.option + ")");
}

}  // namespace urdfsnap::bag
