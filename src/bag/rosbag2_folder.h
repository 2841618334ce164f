// Where a bag's messages are: an MCAP file, a rosbag2 SQLite file (.db3), or a rosbag2 folder as
// `ros2 bag record` makes it: metadata.yaml naming the storage (mcap or sqlite3), its split files
// in order and their compression, or, without metadata.yaml, the folder's .mcap or .db3 files in
// the numbered order of their names.
#pragma once

#include <string>
#include <vector>

namespace urdfsnap::bag {

enum class Storage { kMcap, kSqlite };

// How rosbag2 compressed a bag (metadata.yaml's compression_mode, with compression_format zstd).
enum class Compression {
  kNone,
  kFile,     // each split file whole: NAME_0.mcap.zstd, NAME_0.db3.zstd
  kMessage,  // each message's data on its own
};

struct BagFile {
  std::string path;
  Storage storage = Storage::kMcap;
};

struct BagLayout {
  std::vector<BagFile> files;  // in the order their messages were recorded
  Compression compression = Compression::kNone;
};

// The files of `path`. Throws urdfsnap::Error "PATH: ..." for a folder without bag files, a
// metadata.yaml that cannot be read (bad YAML, an unknown storage or compression, a file it names
// that is missing or outside the folder) or a file of neither kind.
BagLayout FindBagFiles(const std::string& path);

}  // namespace urdfsnap::bag
