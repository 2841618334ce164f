// Two-stage pipelining of numbered work items over two threads: the calling thread produces item
// i (renders frame i, keeping the GL context on the thread that made it) while one worker thread
// consumes item i - 1 (encodes or writes it). A bounded queue sits between them and the items are
// made once and reused, so memory is that of a few items however many pass through: a 10,000-frame
// animation runs in the memory of a 100-frame one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

#include "stream/bounded_queue.h"

namespace urdfsnap::stream {

// Calls produce(i, item) for i = 0, 1, ..., count - 1 on the calling thread and consume(i, item)
// for the same items, in the same order, on one worker thread. At most `depth` produced items wait
// for the consumer; `depth` + 2 items of type Item are default-constructed once and handed out
// again and again (a producer should reuse an item's buffers rather than replace them).
// When either function throws, both sides stop at their next item and the exception is rethrown
// here once the worker has ended (the producer's if both threw). Returns when every item has been
// consumed.
template <typename Item>
void RunPipeline(std::int64_t count, std::size_t depth,
                 const std::function<void(std::int64_t, Item&)>& produce,
                 const std::function<void(std::int64_t, const Item&)>& consume) {
  if (depth < 1) depth = 1;
  std::vector<Item> pool(depth + 2);
  BoundedQueue<Item*> free_items(pool.size());
  for (Item& item : pool) free_items.Push(&item);
  BoundedQueue<std::pair<std::int64_t, Item*>> ready(depth);

  std::exception_ptr consumer_error;
  std::thread worker([&] {
    try {
      while (auto next = ready.Pop()) {
        consume(next->first, *next->second);
        free_items.Push(next->second);
      }
    } catch (...) {
      consumer_error = std::current_exception();
      ready.Cancel();
      free_items.Cancel();
    }
  });

  std::exception_ptr producer_error;
  try {
    for (std::int64_t i = 0; i < count; ++i) {
      const auto item = free_items.Pop();
      if (!item) break;  // the consumer failed
      produce(i, **item);
      if (!ready.Push({i, *item})) break;
    }
    ready.Close();
  } catch (...) {
    producer_error = std::current_exception();
    ready.Cancel();
    free_items.Cancel();
  }
  worker.join();
  if (producer_error) std::rethrow_exception(producer_error);
  if (consumer_error) std::rethrow_exception(consumer_error);
}

}  // namespace urdfsnap::stream
