// BoundedQueue: order, the bound a fast producer meets, closing and cancelling.
#include "stream/bounded_queue.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace urdfsnap::stream {
namespace {

TEST(BoundedQueueTest, HandsOutItemsInOrderThenNothingOnceClosed) {
  BoundedQueue<int> queue(3);
  EXPECT_TRUE(queue.Push(1));
  EXPECT_TRUE(queue.Push(2));
  queue.Close();
  EXPECT_FALSE(queue.Push(3));
  EXPECT_EQ(queue.Pop(), 1);
  EXPECT_EQ(queue.Pop(), 2);
  EXPECT_EQ(queue.Pop(), std::nullopt);
}

TEST(BoundedQueueTest, ProducerNeverRunsMoreThanCapacityAhead) {
  constexpr int kCapacity = 4, kItems = 20000;
  BoundedQueue<int> queue(kCapacity);
  std::atomic<int> pushed{0};
  std::thread producer([&] {
    for (int i = 0; i < kItems; ++i) {
      ASSERT_TRUE(queue.Push(i));
      pushed.fetch_add(1);
    }
    queue.Close();
  });
  int popped = 0;
  while (const auto item = queue.Pop()) {
    ASSERT_EQ(*item, popped);
    ++popped;
    // the producer may have pushed the queue full again, plus the item it is pushing now
    ASSERT_LE(pushed.load() - popped, kCapacity + 1);
  }
  producer.join();
  EXPECT_EQ(popped, kItems);
}

TEST(BoundedQueueTest, CancelReleasesAWaitingProducerAndDropsItems) {
  BoundedQueue<int> queue(1);
  ASSERT_TRUE(queue.Push(0));
  std::atomic<bool> push_result{true};
  std::thread producer([&] { push_result = queue.Push(1); });  // waits: the queue is full
  queue.Cancel();
  producer.join();
  EXPECT_FALSE(push_result);
  EXPECT_EQ(queue.Pop(), std::nullopt);
}

TEST(BoundedQueueTest, CancelReleasesAWaitingConsumer) {
  BoundedQueue<int> queue(2);
  std::optional<int> popped = 7;
  std::thread consumer([&] { popped = queue.Pop(); });  // waits: the queue is empty
  queue.Cancel();
  consumer.join();
  EXPECT_EQ(popped, std::nullopt);
}

}  // namespace
}  // namespace urdfsnap::stream
