// ReadSqliteBag: one read-only connection, two prepared statements, every column's type checked
// before it is used, so that a file that lies about its tables is an error, not a crash.
#include "bag/sqlite_storage.h"

#include <sqlite3.h>

#include <map>
#include <memory>

#include "common/error.h"

namespace urdfsnap::bag {
namespace {

struct CloseDatabase {
  void operator()(sqlite3* db) const { sqlite3_close_v2(db); }
};
struct FinalizeStatement {
  void operator()(sqlite3_stmt* statement) const { sqlite3_finalize(statement); }
};
using Statement = std::unique_ptr<sqlite3_stmt, FinalizeStatement>;

class Database {
 public:
  explicit Database(const std::string& file) : file_(file) {
    sqlite3* db = nullptr;
    const int status = sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
    db_.reset(db);
    if (status != SQLITE_OK) Fail("cannot open it as SQLite");
  }

  Statement Prepare(const char* sql) {
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db_.get(), sql, -1, &statement, nullptr) != SQLITE_OK) {
      Fail("not a rosbag2 SQLite file");
    }
    return Statement(statement);
  }

  // Steps `statement`: true for a row, false at the end.
  bool Step(sqlite3_stmt* statement) {
    const int status = sqlite3_step(statement);
    if (status == SQLITE_ROW) return true;
    if (status != SQLITE_DONE) Fail("cannot read it");
    return false;
  }

  [[noreturn]] void Fail(const std::string& what) const {
    throw Error(file_ + ": " + what + ": " + (db_ ? sqlite3_errmsg(db_.get()) : "out of memory"));
  }

  [[noreturn]] void FailColumn(const std::string& table, std::int64_t row, const char* column,
                               const char* expected) const {
    throw Error(file_ + ": not a rosbag2 SQLite file: row " + std::to_string(row) + " of '" +
                table + "' holds something other than " + expected + " in '" + column + "'");
  }

 private:
  std::string file_;
  std::unique_ptr<sqlite3, CloseDatabase> db_;
};

}  // namespace

void ReadSqliteBag(const std::string& file, const std::function<bool(const SqliteTopic&)>& wanted,
                   const std::function<void(const SqliteTopic&, std::uint64_t timestamp,
                                            std::span<const std::uint8_t> data)>& on_message) {
  Database db(file);
  std::map<std::int64_t, SqliteTopic> topics;  // the wanted ones, by id
  {
    const Statement statement =
        db.Prepare("SELECT id, name, type, serialization_format FROM topics ORDER BY id");
    for (std::int64_t row = 1; db.Step(statement.get()); ++row) {
      if (sqlite3_column_type(statement.get(), 0) != SQLITE_INTEGER) {
        db.FailColumn("topics", row, "id", "an integer");
      }
      SqliteTopic topic;
      topic.id = sqlite3_column_int64(statement.get(), 0);
      std::string* texts[] = {&topic.name, &topic.type, &topic.serialization_format};
      const char* columns[] = {"name", "type", "serialization_format"};
      for (int c = 0; c < 3; ++c) {
        if (sqlite3_column_type(statement.get(), c + 1) != SQLITE_TEXT) {
          db.FailColumn("topics", row, columns[c], "text");
        }
        *texts[c] = reinterpret_cast<const char*>(sqlite3_column_text(statement.get(), c + 1));
      }
      if (wanted(topic)) topics.emplace(topic.id, std::move(topic));
    }
  }
  if (topics.empty()) return;
  const Statement statement =
      db.Prepare("SELECT topic_id, timestamp, data FROM messages ORDER BY timestamp, id");
  for (std::int64_t row = 1; db.Step(statement.get()); ++row) {
    if (sqlite3_column_type(statement.get(), 0) != SQLITE_INTEGER) {
      db.FailColumn("messages", row, "topic_id", "an integer");
    }
    const auto topic = topics.find(sqlite3_column_int64(statement.get(), 0));
    if (topic == topics.end()) continue;
    if (sqlite3_column_type(statement.get(), 1) != SQLITE_INTEGER ||
        sqlite3_column_int64(statement.get(), 1) < 0) {
      db.FailColumn("messages", row, "timestamp", "a time in nanoseconds");
    }
    if (sqlite3_column_type(statement.get(), 2) != SQLITE_BLOB) {
      db.FailColumn("messages", row, "data", "a blob");
    }
    const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(statement.get(), 2));
    const int size = sqlite3_column_bytes(statement.get(), 2);
    on_message(topic->second, static_cast<std::uint64_t>(sqlite3_column_int64(statement.get(), 1)),
               {data, static_cast<std::size_t>(size)});
  }
}

}  // namespace urdfsnap::bag
