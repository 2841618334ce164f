// ProgressBar: throttled redraws with a carriage return and an erase-to-end-of-line escape, the
// terminal's width from the TIOCGWINSZ ioctl.
#include "stream/progress_bar.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace urdfsnap::stream {
namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kDefaultWidth = 80;
// below this many seconds or items a rate would be noise
constexpr double kMinSecondsForRate = 0.25;

int TerminalWidth(std::FILE* out) {
  winsize size{};
  if (::ioctl(::fileno(out), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return kDefaultWidth;
}

std::string Rate(double per_second, const std::string& unit) {
  char text[64];
  std::snprintf(text, sizeof text, per_second >= 100 ? "%.0f %s/s" : "%.1f %s/s", per_second,
                unit.c_str());
  return text;
}

}  // namespace

std::string FormatClock(double seconds) {
  const long long total = std::llround(std::max(0.0, seconds));
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, total / 60 % 60,
                  total % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld:%02lld", total / 60, total % 60);
  }
  return text;
}

std::string FormatProgressLine(std::int64_t done, std::int64_t total, const std::string& unit,
                               double elapsed_seconds, int width) {
  std::string text = "  " + std::to_string(done) + "/" + std::to_string(total) + " " + unit;
  if (elapsed_seconds >= kMinSecondsForRate && done > 0) {
    const double rate = done / elapsed_seconds;
    text += "  " + Rate(rate, unit);
    if (done < total) text += "  " + FormatClock((total - done) / rate) + " left";
  }
  // the bar gets what is left of the line, if that is enough to show movement
  const int bar_width = width - 1 - static_cast<int>(text.size()) - 2;
  if (bar_width >= 10) {
    const double fraction = total > 0 ? std::clamp(double(done) / total, 0.0, 1.0) : 1.0;
    const int filled = static_cast<int>(fraction * bar_width);
    std::string bar(bar_width, ' ');
    std::fill_n(bar.begin(), filled, '=');
    if (filled < bar_width) bar[filled] = '>';
    text = "[" + bar + "]" + text;
  }
  if (static_cast<int>(text.size()) > width - 1) text.resize(std::max(0, width - 1));
  return text;
}

ProgressBar::ProgressBar(std::int64_t total, std::string unit, Display display, std::FILE* out)
    : total_(total),
      unit_(std::move(unit)),
      out_(out),
      shown_(display == Display::kAlways ||
             (display == Display::kIfTerminal && ::isatty(::fileno(out)))),
      reported_(display != Display::kNever) {}

ProgressBar::~ProgressBar() {
  if (shown_ && !finished_) Draw("");
}

double ProgressBar::Elapsed() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressBar::Draw(const std::string& line) {
  std::fputs(("\r" + line + "\x1b[K").c_str(), out_);
  std::fflush(out_);
}

void ProgressBar::Update(std::int64_t done) {
  done_ = done;
  if (!shown_) return;
  const Clock::time_point now = Clock::now();
  if (done < total_ && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  Draw(FormatProgressLine(done, total_, unit_, Elapsed(), TerminalWidth(out_)));
}

void ProgressBar::Finish(const std::string& result) {
  if (!reported_ || finished_) return;
  finished_ = true;
  const double seconds = Elapsed();
  char text[160];
  std::snprintf(text, sizeof text, "%lld %s in %.1f s", static_cast<long long>(done_),
                unit_.c_str(), seconds);
  std::string line = (result.empty() ? "" : result + ": ") + text;
  if (seconds > 0 && done_ > 0) line += " (" + Rate(done_ / seconds, unit_) + ")";
  if (shown_) {
    Draw(line);
  } else {
    std::fputs(line.c_str(), out_);
  }
  std::fputc('\n', out_);
  std::fflush(out_);
}

}  // namespace urdfsnap::stream
