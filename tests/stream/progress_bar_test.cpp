// The progress line's text, and that only the summary is written where the stream is not a
// terminal.
#include "stream/progress_bar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace urdfsnap::stream {
namespace {

// What a progress bar of `total` items writes to its stream while `use` drives it.
template <typename Use>
std::string Written(std::int64_t total, ProgressBar::Display display, Use use) {
  std::FILE* file = std::tmpfile();
  EXPECT_NE(file, nullptr);
  {
    ProgressBar bar(total, "frames", display, file);
    use(bar);
  }
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
  std::fclose(file);
  return text;
}

TEST(ProgressLineTest, ShowsCountRateAndTimeLeftWithABarThatFitsTheWidth) {
  const std::string line = FormatProgressLine(250, 1000, "frames", 1.0, 80);
  EXPECT_EQ(line.size(), 79u);
  EXPECT_EQ(line.front(), '[');
  EXPECT_NE(line.find("] "), std::string::npos);
  EXPECT_NE(line.find("250/1000 frames  250 frames/s  0:03 left"), std::string::npos) << line;
  // a quarter of the bar is filled (rounded down)
  const std::size_t bar = line.find(']') - 1;
  const std::size_t filled = line.find('>') - 1;
  EXPECT_EQ(filled, bar / 4) << line;
}

TEST(ProgressLineTest, NoRateBeforeThereIsAnythingToMeasure) {
  EXPECT_EQ(FormatProgressLine(0, 50, "frames", 0.0, 20), "  0/50 frames");
  const std::string line = FormatProgressLine(3, 50, "frames", 0.01, 200);
  EXPECT_EQ(line.find("/s"), std::string::npos) << line;
}

TEST(ProgressLineTest, NarrowTerminalsGetNoBarAndATruncatedLine) {
  const std::string line = FormatProgressLine(5, 10, "frames", 2.0, 24);
  EXPECT_EQ(line.find('['), std::string::npos);
  EXPECT_LE(line.size(), 23u);
}

TEST(ProgressLineTest, ClockFormat) {
  EXPECT_EQ(FormatClock(0), "0:00");
  EXPECT_EQ(FormatClock(65.4), "1:05");
  EXPECT_EQ(FormatClock(3600 * 12 + 3), "12:00:03");
}

TEST(ProgressBarTest, WritesOnlyTheSummaryToAFileThatIsNotATerminal) {
  const std::string text = Written(10, ProgressBar::Display::kIfTerminal, [](ProgressBar& bar) {
    EXPECT_FALSE(bar.shown());
    for (int i = 1; i <= 10; ++i) bar.Update(i);
    bar.Finish("wrote out.mp4 (1.2 MB)");
  });
  EXPECT_EQ(text.rfind("wrote out.mp4 (1.2 MB): 10 frames in ", 0), 0u) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressBarTest, AnUnfinishedBarOffATerminalWritesNothing) {
  EXPECT_EQ(Written(10, ProgressBar::Display::kIfTerminal, [](ProgressBar& bar) { bar.Update(5); }), "");
}

TEST(ProgressBarTest, QuietWritesNothing) {
  EXPECT_EQ(Written(10, ProgressBar::Display::kNever,
                    [](ProgressBar& bar) {
                      bar.Update(10);
                      bar.Finish();
                    }),
            "");
}

TEST(ProgressBarTest, DrawsInPlaceAndEndsWithASummaryLine) {
  const std::string text = Written(3, ProgressBar::Display::kAlways, [](ProgressBar& bar) {
    bar.Update(1);
    bar.Update(3);  // the last item is always drawn
    bar.Finish();
  });
  EXPECT_EQ(text.find("\r"), 0u);
  EXPECT_NE(text.find("3/3 frames"), std::string::npos) << text;
  EXPECT_NE(text.find("3 frames in "), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressBarTest, AnUnfinishedBarClearsItsLineForTheErrorMessage) {
  const std::string text =
      Written(100, ProgressBar::Display::kAlways, [](ProgressBar& bar) { bar.Update(100); });
  EXPECT_EQ(text.substr(text.size() - 4), "\r\x1b[K");
}

}  // namespace
}  // namespace urdfsnap::stream
