// BagDisplayFeed: ReadBagMessages on a thread of its own pushing decoded messages into a
// stream::BoundedQueue, the displays fed on the caller's thread (warnings are touched there only).
#include "display/bag_display_feed.h"

#include <utility>

#include "bag/bag_messages.h"
#include "bag/cdr_reader.h"
#include "common/error.h"

namespace urdfsnap::display {
namespace {

// Thrown through ReadBagMessages to end the reader once the feed is no longer wanted.
struct Stopped {};

}  // namespace

BagDisplayFeed::BagDisplayFeed(std::string path, DisplaySet& displays)
    : path_(std::move(path)), displays_(displays) {}

BagDisplayFeed::~BagDisplayFeed() {
  queue_.Cancel();
  if (reader_.joinable()) reader_.join();
}

void BagDisplayFeed::Read() {
  try {
    bag::ReadBagMessages(
        path_,
        [&](const bag::BagTopic& topic) { return topic.encoding == "cdr" && displays_.Subscribes(topic.name); },
        [&](const bag::BagMessage& message) {
          Item item;
          item.time_ns = static_cast<std::int64_t>(message.log_time);
          item.topic = message.topic.name;
          item.type = message.topic.type;
          item.schema = message.topic.schema;
          item.where = bag::DescribeMessage(message.file, message.topic.name, message.index, message.log_time);
          try {
            item.value = bag::DecodeMessage(*message.topic.schema, message.data);
          } catch (const bag::CdrError& e) {
            item.problem = e.what();
          }
          if (!queue_.Push(std::move(item))) throw Stopped{};
        });
  } catch (const Stopped&) {
    return;
  } catch (...) {
    Item failed;
    failed.error = std::current_exception();
    queue_.Push(std::move(failed));
  }
  queue_.Close();
}

void BagDisplayFeed::AdvanceTo(std::int64_t until_ns, Warnings& warnings) {
  if (displays_.empty() || finished_) return;
  if (!started_) {
    started_ = true;
    reader_ = std::thread([this] { Read(); });
  }
  while (true) {
    if (!next_) next_ = queue_.Pop();
    if (!next_) {   // the bag's end
      finished_ = true;
      return;
    }
    Item& item = *next_;
    if (item.error) {
      finished_ = true;
      std::rethrow_exception(item.error);
    }
    if (item.time_ns > until_ns) return;
    if (item.value) {
      try {
        displays_.Receive(item.topic, item.type, *item.value, item.time_ns, item.where, warnings);
      } catch (...) {
        finished_ = true;
        throw;
      }
    } else {
      warnings.Add(item.where + ": " + item.problem + "; not drawn");
    }
    next_.reset();
  }
}

}  // namespace urdfsnap::display
