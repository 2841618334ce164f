// FindBagFiles: metadata.yaml read with yaml-cpp (rosbag2_storage's metadata_io.cpp names its
// keys: rosbag2_bagfile_information, storage_identifier, relative_file_paths, compression_format,
// compression_mode), else the folder listed; a file taken by its first bytes (SQLite's header or
// MCAP's magic), whatever its extension.
#include "bag/rosbag2_folder.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <yaml-cpp/yaml.h>

#include "common/error.h"
#include "common/file_reading.h"
#include "common/internal/yaml_reader.h"

namespace urdfsnap::bag {
namespace {

namespace fs = std::filesystem;

// The number at the end of a split file's stem ("run_12.mcap" -> 12), or -1.
long long SplitNumber(const fs::path& file) {
  std::string stem = file.filename().string();
  stem = stem.substr(0, stem.find('.'));
  const std::size_t digits = stem.find_last_not_of("0123456789") + 1;
  if (digits == stem.size() || stem.size() - digits > 15) return -1;
  return std::stoll(stem.substr(digits));
}

bool EndsWith(const fs::path& file, std::string_view tail) {
  return file.filename().string().ends_with(tail);
}

// A single file: SQLite's 16-byte header string, else MCAP (its reader checks the magic).
Storage StorageOf(const std::string& path) {
  char header[16] = {};
  std::ifstream(path, std::ios::binary).read(header, sizeof header);
  return std::memcmp(header, "SQLite format 3", 16) == 0 ? Storage::kSqlite : Storage::kMcap;
}

// The folder's .mcap or .db3 files (plain or .zstd), by the numbers at the end of their names.
BagLayout ListFolder(const std::string& path) {
  std::error_code error;
  std::vector<fs::path> mcap, db3;
  for (const auto& entry : fs::directory_iterator(path, error)) {
    if (EndsWith(entry.path(), ".mcap") || EndsWith(entry.path(), ".mcap.zstd")) {
      mcap.push_back(entry.path());
    }
    if (EndsWith(entry.path(), ".db3") || EndsWith(entry.path(), ".db3.zstd")) {
      db3.push_back(entry.path());
    }
  }
  if (error) throw Error(path + ": cannot read the folder: " + error.message());
  if (mcap.empty() && db3.empty()) {
    throw Error(path + ": a folder without metadata.yaml, .mcap or .db3 files: not a ROS 2 bag");
  }
  if (!mcap.empty() && !db3.empty()) {
    throw Error(path + ": a folder with both .mcap and .db3 files and no metadata.yaml to say "
                       "which are the bag");
  }
  std::vector<fs::path>& files = mcap.empty() ? db3 : mcap;
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return std::pair(SplitNumber(a), a.string()) < std::pair(SplitNumber(b), b.string());
  });
  BagLayout layout;
  for (const fs::path& file : files) {
    layout.files.push_back({file.string(), mcap.empty() ? Storage::kSqlite : Storage::kMcap});
    if (EndsWith(file, ".zstd")) layout.compression = Compression::kFile;
  }
  return layout;
}

BagLayout FromMetadata(const fs::path& folder, const fs::path& metadata_path) {
  const std::string where = metadata_path.string();
  std::string text;
  try {
    text = ReadFileBounded(where);
  } catch (const FileReadError& e) {
    throw Error(where + ": cannot read it: " + e.what());
  }
  const YamlReader reader(where);
  YAML::Node root = reader.Load(text);
  const YAML::Node info = root.IsMap() ? root["rosbag2_bagfile_information"] : YAML::Node();
  if (!info.IsDefined() || !info.IsMap()) {
    reader.Fail(root, "expected rosbag2's 'rosbag2_bagfile_information' map");
  }
  const auto text_of = [&](const char* key) {
    const YAML::Node node = info[key];
    if (!node.IsDefined() || node.IsNull()) return std::string();
    if (!node.IsScalar()) reader.Fail(node, std::string("'") + key + "': expected text");
    return node.Scalar();
  };
  BagLayout layout;
  const std::string storage = text_of("storage_identifier");
  if (storage != "mcap" && storage != "sqlite3") {
    reader.Fail(info["storage_identifier"], "storage_identifier '" + storage +
                                         "': urdfsnap reads 'mcap' and 'sqlite3' bags");
  }
  const std::string format = text_of("compression_format");
  const std::string mode = text_of("compression_mode");
  if (!format.empty() && format != "zstd") {
    reader.Fail(info["compression_format"], "compression_format '" + format + "': urdfsnap reads zstd");
  }
  if (mode == "FILE" || mode == "file") {
    layout.compression = Compression::kFile;
  } else if (mode == "MESSAGE" || mode == "message") {
    layout.compression = Compression::kMessage;
  } else if (!mode.empty() && mode != "NONE" && mode != "none") {
    reader.Fail(info["compression_mode"], "compression_mode '" + mode + "': expected FILE or MESSAGE");
  }
  const YAML::Node paths = info["relative_file_paths"];
  if (!paths.IsDefined()) {  // hand-written metadata: the folder's files, as without it
    const BagLayout listed = ListFolder(folder.string());
    if ((listed.files.front().storage == Storage::kMcap) != (storage == "mcap")) {
      reader.Fail(info["storage_identifier"], "storage_identifier '" + storage +
                                           "', but the folder holds the other kind of files");
    }
    layout.files = listed.files;
    return layout;
  }
  if (!paths.IsSequence() || paths.size() == 0) {
    reader.Fail(paths, "'relative_file_paths': expected a list of files");
  }
  for (const YAML::Node& item : paths) {
    if (!item.IsScalar()) reader.Fail(item, "'relative_file_paths': expected file names");
    // rosbag2 writes names relative to the folder (older versions: with the folder's name first)
    fs::path file = folder / fs::path(item.Scalar()).filename();
    if (fs::path(item.Scalar()).is_absolute() || item.Scalar().find("..") != std::string::npos) {
      reader.Fail(item, "'" + item.Scalar() + "': expected a file in the bag's folder");
    }
    std::error_code error;
    if (!fs::is_regular_file(file, error)) {
      reader.Fail(item, "'" + item.Scalar() + "': no such file in " + folder.string());
    }
    layout.files.push_back({file.string(), storage == "mcap" ? Storage::kMcap : Storage::kSqlite});
  }
  return layout;
}

}  // namespace

BagLayout FindBagFiles(const std::string& path) {
  std::error_code error;
  if (!fs::is_directory(path, error)) {
    BagLayout layout;
    layout.files.push_back({path, StorageOf(path)});
    return layout;
  }
  const fs::path folder(path);
  if (fs::exists(folder / "metadata.yaml", error)) {
    return FromMetadata(folder, folder / "metadata.yaml");
  }
  return ListFolder(path);
}

}  // namespace urdfsnap::bag
