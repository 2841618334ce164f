// ReadBagMessages: each file of the layout through McapReader or ReadSqliteBag (whole-file zstd
// decompressed into a temporary file first, per-message zstd per message), topics keyed by name
// and type so that a definition is parsed once for the whole bag.
#include "bag/bag_messages.h"

#include <cinttypes>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "bag/internal/chunk_decompressor.h"
#include "bag/mcap_reader.h"
#include "bag/rosbag2_folder.h"
#include "bag/sqlite_storage.h"
#include "bag/zstd_file.h"
#include "common/error.h"

namespace urdfsnap::bag {
namespace {

// The topics met so far, by name and type, each with its message count and definition.
class Topics {
 public:
  // The topic as it stays for the rest of the bag.
  BagTopic& Find(const std::string& name, const std::string& type, const std::string& encoding) {
    auto [entry, added] = topics_.try_emplace({name, type});
    if (added) entry->second.topic = {name, type, encoding, nullptr};
    return entry->second.topic;
  }

  std::uint64_t& Count(const BagTopic& topic) { return topics_.at({topic.name, topic.type}).count; }

 private:
  struct Entry {
    BagTopic topic;
    std::uint64_t count = 0;
  };
  std::map<std::pair<std::string, std::string>, Entry> topics_;
};

// Gives `topic` its definition: `text` when the bag has one in ros2msg, else urdfsnap's.
void Define(BagTopic& topic, const std::string& file, const std::string& encoding,
            const std::string& text) {
  if (topic.schema) return;
  try {
    if (encoding == "ros2msg" && !text.empty()) {
      topic.schema = std::make_shared<MessageSchema>(MessageSchema::Parse(topic.type, text));
    } else if (auto shipped = MessageSchema::Shipped(topic.type)) {
      topic.schema = std::make_shared<MessageSchema>(std::move(*shipped));
    }
  } catch (const SchemaError& e) {
    throw Error(file + ": topic '" + topic.name + "': its definition of '" + topic.type +
                "' cannot be read: " + e.what());
  }
  if (!topic.schema) {
    throw Error(file + ": topic '" + topic.name + "' carries '" + topic.type + "'" +
                (encoding.empty() ? "" : " defined in '" + encoding + "'") +
                ", and the bag holds no ros2msg definition of it that urdfsnap could use");
  }
}

// Reads one storage file (`readable`: the file, or its decompressed copy; `file` names it).
void ReadFile(Storage storage, const std::string& readable, const std::string& file,
              Topics& topics, const std::function<bool(const BagTopic&)>& wanted,
              const std::function<void(BagTopic&, std::uint64_t, std::span<const std::uint8_t>)>&
                  deliver) {
  if (storage == Storage::kSqlite) {
    std::map<std::int64_t, BagTopic*> by_id;
    ReadSqliteBag(
        readable,
        [&](const SqliteTopic& row) {
          BagTopic& topic = topics.Find(row.name, row.type, row.serialization_format);
          if (!wanted(topic)) return false;
          Define(topic, file, "", "");  // a .db3 stores no definitions
          by_id[row.id] = &topic;
          return true;
        },
        [&](const SqliteTopic& row, std::uint64_t timestamp, std::span<const std::uint8_t> data) {
          deliver(*by_id.at(row.id), timestamp, data);
        });
    return;
  }
  McapReader reader(readable);
  std::map<std::uint16_t, BagTopic*> by_channel;
  reader.ReadMessages(
      [&](const McapChannel& channel) {
        BagTopic& topic = topics.Find(channel.topic, channel.schema_name, channel.message_encoding);
        if (!wanted(topic)) return false;
        Define(topic, file, channel.schema_encoding, channel.schema_data);
        by_channel[channel.id] = &topic;
        return true;
      },
      [&](const McapMessage& message) {
        deliver(*by_channel.at(message.channel->id), message.log_time, message.data);
      });
}

}  // namespace

std::string TimeText(std::uint64_t time_ns) {
  char time[48];
  std::snprintf(time, sizeof time, "%" PRIu64 ".%09" PRIu64, time_ns / 1'000'000'000, time_ns % 1'000'000'000);
  return time;
}

std::string DescribeMessage(const std::string& file, const std::string& topic, std::uint64_t index,
                            std::uint64_t log_time) {
  return file + ": message " + std::to_string(index) + " on '" + topic + "' (log time " + TimeText(log_time) + " s)";
}

void ReadBagMessages(const std::string& path, const std::function<bool(const BagTopic&)>& wanted,
                     const std::function<void(const BagMessage&)>& on_message) {
  const BagLayout layout = FindBagFiles(path);
  Topics topics;
  ChunkDecompressor decompressor;
  std::vector<std::uint8_t> message_buffer;  // a message decompressed (compression_mode MESSAGE)
  for (const BagFile& bag_file : layout.files) {
    const std::string& file = bag_file.path;
    std::optional<ZstdFileCopy> copy;
    if (layout.compression == Compression::kFile) copy.emplace(file);
    const std::string& readable = copy ? copy->path() : file;
    const auto deliver = [&](BagTopic& topic, std::uint64_t log_time,
                             std::span<const std::uint8_t> data) {
      const std::uint64_t index = ++topics.Count(topic);
      if (layout.compression == Compression::kMessage) {
        try {
          data = DecompressZstdMessage(data, message_buffer);
        } catch (const std::runtime_error& e) {
          throw Error(DescribeMessage(file, topic.name, index, log_time) + ": " + e.what());
        }
      }
      on_message(BagMessage{topic, file, index, log_time, data});
    };

    try {
      ReadFile(bag_file.storage, readable, file, topics, wanted, deliver);
    } catch (const Error& e) {
      if (!copy) throw;
      // name the bag's file, not the temporary copy
      std::string message = e.what();
      for (std::size_t at; (at = message.find(copy->path())) != std::string::npos;) {
        message.replace(at, copy->path().size(), file);
      }
      throw Error(message);
    }
  }
}

}  // namespace urdfsnap::bag
