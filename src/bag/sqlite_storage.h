// Reading rosbag2's SQLite storage (.db3, rosbag2_storage_sqlite3) through Debian's libsqlite3:
// the 'topics' table (id, name, type, serialization_format) and the 'messages' table (topic_id,
// timestamp, data), read-only, in the order rosbag2 plays them (by timestamp). A .db3 holds no
// message definitions; the caller brings them.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace urdfsnap::bag {

struct SqliteTopic {
  std::int64_t id = 0;
  std::string name;                  // "/joint_states"
  std::string type;                  // "sensor_msgs/msg/JointState"
  std::string serialization_format;  // "cdr"
};

// Calls `wanted` for every topic of the file's topics table, then `on_message` for every message on
// a wanted topic, by timestamp (nanoseconds). Throws urdfsnap::Error "FILE: ..." for a file that is
// not SQLite, lacks rosbag2's tables or columns, or holds values of other types in them (a
// timestamp that is no integer, data that is no blob). Exceptions from the callbacks pass through.
void ReadSqliteBag(const std::string& file, const std::function<bool(const SqliteTopic&)>& wanted,
                   const std::function<void(const SqliteTopic&, std::uint64_t timestamp,
                                            std::span<const std::uint8_t> data)>& on_message);

}  // namespace urdfsnap::bag
