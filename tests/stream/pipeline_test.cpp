// RunPipeline: every item consumed once in order, a fixed set of reused items however many pass,
// and errors from either side stopping both and reaching the caller.
#include "stream/pipeline.h"

#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <vector>

namespace urdfsnap::stream {
namespace {

// a frame-like item: a large buffer that a producer fills in place
struct Frame {
  std::vector<int> pixels;
};

TEST(PipelineTest, ConsumesEveryItemInOrderFromAFixedPoolOfItems) {
  constexpr std::int64_t kCount = 10000;
  constexpr std::size_t kDepth = 3;
  std::set<const Frame*> items_seen;
  std::set<const int*> buffers_seen;
  std::int64_t next_expected = 0;
  RunPipeline<Frame>(
      kCount, kDepth,
      [](std::int64_t i, Frame& frame) {
        frame.pixels.resize(1000);
        frame.pixels.assign(frame.pixels.size(), static_cast<int>(i));
      },
      [&](std::int64_t i, const Frame& frame) {
        ASSERT_EQ(i, next_expected++);
        ASSERT_EQ(frame.pixels.front(), i);
        ASSERT_EQ(frame.pixels.back(), i);
        items_seen.insert(&frame);
        buffers_seen.insert(frame.pixels.data());
      });
  EXPECT_EQ(next_expected, kCount);
  // memory independent of the count: depth + 2 items, each with the buffer it was given once
  EXPECT_EQ(items_seen.size(), kDepth + 2);
  EXPECT_EQ(buffers_seen.size(), kDepth + 2);
}

TEST(PipelineTest, AConsumerErrorStopsTheProducerAndReachesTheCaller) {
  std::atomic<std::int64_t> produced{0};
  EXPECT_THROW(RunPipeline<Frame>(
                   1000000, 2, [&](std::int64_t, Frame&) { produced.fetch_add(1); },
                   [](std::int64_t i, const Frame&) {
                     if (i == 10) throw std::runtime_error("disk full");
                   }),
               std::runtime_error);
  // the producer stopped within the queue's reach of the failed item
  EXPECT_LE(produced.load(), 10 + 2 + 2 + 1);
}

TEST(PipelineTest, AProducerErrorStopsTheConsumerAndReachesTheCaller) {
  std::int64_t consumed = 0;
  try {
    RunPipeline<Frame>(
        1000, 4,
        [](std::int64_t i, Frame&) {
          if (i == 5) throw std::invalid_argument("render failed");
        },
        [&](std::int64_t, const Frame&) { ++consumed; });
    FAIL() << "expected the producer's exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "render failed");
  }
  EXPECT_LE(consumed, 5);
}

TEST(PipelineTest, NoItemsIsNoCalls) {
  int calls = 0;
  RunPipeline<Frame>(
      0, 2, [&](std::int64_t, Frame&) { ++calls; }, [&](std::int64_t, const Frame&) { ++calls; });
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace urdfsnap::stream
