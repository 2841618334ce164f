// A bag's messages fed to displays as time moves forward, for animations: one reader thread reads
// the bag once, in its order, decoding the messages of the displays' topics into a short queue, and
// AdvanceTo(t) gives the displays every message logged up to t. Memory holds a few messages and
// what the displays keep (display/display.h), however long the bag: nothing is read twice and
// nothing is read ahead of the queue.
#pragma once

#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "bag/cdr_message.h"
#include "common/warnings.h"
#include "display/display_set.h"
#include "stream/bounded_queue.h"

namespace urdfsnap::display {

class BagDisplayFeed {
 public:
  // Feeds `displays` (kept by reference) from the bag at `path`; nothing is read until AdvanceTo.
  BagDisplayFeed(std::string path, DisplaySet& displays);
  // Stops the reader (it may be waiting for room in the queue) and waits for it.
  ~BagDisplayFeed();
  BagDisplayFeed(const BagDisplayFeed&) = delete;
  BagDisplayFeed& operator=(const BagDisplayFeed&) = delete;

  // Gives the displays every message on their topics logged at or before `until_ns` that an
  // earlier call has not given them, in the bag's order, stopping at the first one logged later
  // (rosbag2 writes in log-time order). A message that does not decode (a marker claiming more
  // points than its bytes hold) is a warning naming it, and is skipped. Throws urdfsnap::Error for
  // an unreadable bag or a message that lacks a field a display reads; the feed then gives nothing
  // more.
  void AdvanceTo(std::int64_t until_ns, Warnings& warnings);

  // Messages decoded ahead of the displays at most.
  static constexpr std::size_t kQueued = 8;

 private:
  struct Item {
    std::int64_t time_ns = 0;
    std::string topic, type, where;
    std::optional<bag::MessageValue> value;   // unset when it did not decode
    std::shared_ptr<const bag::MessageSchema> schema;   // what `value` points into
    std::string problem;                      // why it did not decode
    std::exception_ptr error;                 // the bag could not be read further
  };
  void Read();

  std::string path_;
  DisplaySet& displays_;
  stream::BoundedQueue<Item> queue_{kQueued};
  std::optional<Item> next_;   // taken from the queue, logged after the last AdvanceTo's time
  bool started_ = false;
  bool finished_ = false;
  std::thread reader_;
};

}  // namespace urdfsnap::display
