// ReadJointStates: McapReader over each file of the bag, channel checks, CDR decoding with located
// errors.
#include "bag/joint_state_bag.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <map>
#include <system_error>

#include "bag/cdr_reader.h"
#include "bag/mcap_reader.h"
#include "common/error.h"

namespace urdfsnap::bag {
namespace {

namespace fs = std::filesystem;

// The number at the end of a split file's stem ("run_12.mcap" -> 12), or -1.
long long SplitNumber(const fs::path& file) {
  const std::string stem = file.stem().string();
  const std::size_t digits = stem.find_last_not_of("0123456789") + 1;
  if (digits == stem.size() || stem.size() - digits > 15) return -1;
  return std::stoll(stem.substr(digits));
}

std::string TopicList(const std::map<std::string, std::string>& topics) {
  std::string list;
  for (const auto& [topic, type] : topics) {
    list += (list.empty() ? "" : ", ") + topic + " (" + (type.empty() ? "no schema" : type) + ")";
  }
  return list;
}

}  // namespace

std::string DescribeMessage(const std::string& file, const std::string& topic, std::uint64_t index,
                            std::uint64_t log_time) {
  char time[48];
  std::snprintf(time, sizeof time, "%" PRIu64 ".%09" PRIu64, log_time / 1'000'000'000,
                log_time % 1'000'000'000);
  return file + ": message " + std::to_string(index) + " on '" + topic + "' (log time " + time +
         " s)";
}

std::vector<std::string> BagFiles(const std::string& path) {
  std::error_code error;
  if (!fs::is_directory(path, error)) return {path};
  std::vector<fs::path> mcap, db3;
  for (const auto& entry : fs::directory_iterator(path, error)) {
    if (entry.path().extension() == ".mcap") mcap.push_back(entry.path());
    if (entry.path().extension() == ".db3") db3.push_back(entry.path());
  }
  if (error) throw Error(path + ": cannot read the folder: " + error.message());
  if (mcap.empty()) {
    throw Error(path + ": a folder without .mcap files" +
                (db3.empty() ? std::string()
                             : "; it holds SQLite rosbag2 files (.db3), and urdfsnap reads MCAP "
                               "bags (convert with `ros2 bag convert`, or record with "
                               "`--storage mcap`)"));
  }
  std::sort(mcap.begin(), mcap.end(), [](const fs::path& a, const fs::path& b) {
    return std::pair(SplitNumber(a), a.string()) < std::pair(SplitNumber(b), b.string());
  });
  std::vector<std::string> files;
  for (const fs::path& file : mcap) files.push_back(file.string());
  return files;
}

void ReadJointStates(const std::string& path, const std::string& topic,
                     const std::function<void(const BagJointState&)>& on_state) {
  std::map<std::string, std::string> topics;  // every topic seen, with its type
  bool has_topic = false;
  std::uint64_t index = 0;
  JointStateMessage decoded;
  for (const std::string& file : BagFiles(path)) {
    McapReader reader(file);
    const auto wanted = [&](const McapChannel& channel) {
      topics.emplace(channel.topic, channel.schema_name);
      if (channel.topic != topic) return false;
      if (channel.schema_name != kJointStateType || channel.message_encoding != "cdr") {
        throw Error(file + ": topic '" + topic + "' carries '" + channel.schema_name +
                    "' messages encoded as '" + channel.message_encoding + "'; urdfsnap reads " +
                    kJointStateType + " in 'cdr' (ROS 2)");
      }
      has_topic = true;
      return true;
    };
    reader.ReadMessages(wanted, [&](const McapMessage& message) {
      ++index;
      try {
        DecodeJointState(message.data, decoded);
      } catch (const CdrError& e) {
        throw Error(DescribeMessage(file, topic, index, message.log_time) +
                    ": not a JointState in CDR: " + e.what());
      }
      on_state(BagJointState{decoded, file, index, message.log_time});
    });
  }
  if (!has_topic) {
    throw Error(path + ": no topic '" + topic + "' in the bag; " +
                (topics.empty() ? std::string("it has no topics")
                                : "its topics are: " + TopicList(topics)));
  }
  if (index == 0) throw Error(path + ": no messages on '" + topic + "'");
}

}  // namespace urdfsnap::bag
