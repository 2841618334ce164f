// A progress bar for long work on one line of a terminal, redrawn in place:
//   [==========>            ]  412/1000 frames  297 frames/s  0:02 left
// drawn only when its stream is a terminal, and replaced by a one-line summary when the work is
// done; a pipe or a log file (CI) gets the summary line alone, so that logs say what was made.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace urdfsnap::stream {

// The text of one progress line, at most `width` characters: a bar when there is room for one,
// then "done/total unit", the rate in units per second and the time left once `elapsed_seconds`
// allows an estimate. Pure, for tests.
std::string FormatProgressLine(std::int64_t done, std::int64_t total, const std::string& unit,
                               double elapsed_seconds, int width);

// "1:05", "12:00:03": whole seconds as [h:]mm:ss (m:ss under an hour).
std::string FormatClock(double seconds);

class ProgressBar {
 public:
  enum class Display { kIfTerminal, kAlways, kNever };

  // Progress of `total` items called `unit` ("frames") on `out`. kIfTerminal draws the bar only
  // when `out` is a terminal and the summary in any case; kNever is --quiet (nothing); kAlways
  // draws the bar anywhere, for tests.
  ProgressBar(std::int64_t total, std::string unit, Display display = Display::kIfTerminal,
              std::FILE* out = stderr);
  // Clears the line if Finish was not called (an error is about to be printed there).
  ~ProgressBar();

  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` items are complete. Redraws at most ten times a second, and always at the last item.
  // Call from one thread at a time.
  void Update(std::int64_t done);

  // Replaces the bar (or, off a terminal, writes a line) with "RESULT: 1000 frames in 3.4 s (297
  // frames/s)" and a newline, `result` saying what was made ("wrote run.mp4 (1.2 MB)") or empty.
  void Finish(const std::string& result = "");

  bool shown() const { return shown_; }

 private:
  using Clock = std::chrono::steady_clock;
  double Elapsed() const;
  void Draw(const std::string& line);

  std::int64_t total_;
  std::string unit_;
  std::FILE* out_;
  bool shown_;      // the bar is drawn
  bool reported_;   // the summary is written
  bool finished_ = false;
  std::int64_t done_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_{};
};

}  // namespace urdfsnap::stream
