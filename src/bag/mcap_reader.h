// Reading messages from an MCAP file (the container of ROS 2 bags since Iron), written here from
// the format's specification (mcap.dev/spec): magic, Header, then the data section's records in
// file order, with chunks of Schema/Channel/Message records uncompressed or compressed with zstd or
// lz4. It streams: one chunk is in memory at a time (its declared size checked against a limit
// before anything is allocated), records the caller does not want are skipped unread; of the
// summary section only the channel list is read. Truncated and corrupt files end in an Error naming
// the byte where it went wrong.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace urdfsnap::bag {

// The largest chunk (compressed or not) and the largest record outside a chunk that the reader
// loads into memory: far above rosbag2's chunks (under 10 MiB even with camera images in them),
// and a bound on what a corrupt size field can make it allocate.
inline constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{512} << 20;
inline constexpr std::uint64_t kMaxRecordBytes = std::uint64_t{64} << 20;

// A Channel record with its Schema's name and encoding ("" when the channel has no schema).
struct McapChannel {
  std::uint16_t id = 0;
  std::string topic;
  std::string message_encoding;  // "cdr" for ROS 2
  std::string schema_name;       // "sensor_msgs/msg/JointState"
  std::string schema_encoding;   // "ros2msg"
  std::string schema_data;       // the definition: .msg text for ros2msg
};

// One Message record, valid during the callback that receives it.
struct McapMessage {
  const McapChannel* channel = nullptr;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;      // nanoseconds
  std::uint64_t publish_time = 0;  // nanoseconds
  std::span<const std::uint8_t> data;
};

class McapReader {
 public:
  // Opens `path` and checks that it starts with MCAP's magic and Header record and ends with the
  // magic. Throws urdfsnap::Error "path: ..." when it cannot be read, is not MCAP or is truncated.
  explicit McapReader(const std::string& path);
  ~McapReader();

  McapReader(const McapReader&) = delete;
  McapReader& operator=(const McapReader&) = delete;

  // Reads the data section from its start to the Data End record, then the summary's Schema and
  // Channel records. Each channel is passed to `wanted` once, when its Channel record is first met
  // (a channel without messages may appear only in the summary); each message on a wanted channel
  // then goes to `on_message`. Exceptions from the callbacks pass through. Throws urdfsnap::Error
  // for a truncated or corrupt file ("path: corrupt MCAP: the chunk at byte 4096: ..."). Call it
  // once.
  void ReadMessages(const std::function<bool(const McapChannel&)>& wanted,
                    const std::function<void(const McapMessage&)>& on_message);

  // The channels met so far (all of them after ReadMessages), in order of their ids.
  std::vector<const McapChannel*> channels() const;

  const std::string& profile() const { return profile_; }  // "ros2" for rosbag2's files
  const std::string& library() const { return library_; }  // the writer's name and version

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::string profile_;
  std::string library_;
};

}  // namespace urdfsnap::bag
