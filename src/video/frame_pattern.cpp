// FramePattern: a small parser for one %[0][width]d conversion.
#include "video/frame_pattern.h"

#include <cctype>
#include <cstdio>
#include <vector>

#include "common/error.h"

namespace urdfsnap::video {
namespace {

// The widest zero padding accepted: more digits than any frame count.
constexpr int kMaxWidth = 12;

struct Conversion {
  std::size_t start = 0, end = 0;  // [start, end) in the pattern
  int width = 0;
  bool zero_pad = false;
};

// Finds the conversions of `pattern`; `literal` receives the text with "%%" collapsed, and a
// conversion that is not an integer one is an error.
std::vector<Conversion> Conversions(const std::string& pattern) {
  std::vector<Conversion> found;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;
      continue;
    }
    Conversion conversion{i, i + 1};
    std::size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') {
      conversion.zero_pad = true;
      ++j;
    }
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) {
      conversion.width = conversion.width * 10 + (pattern[j] - '0');
      if (conversion.width > kMaxWidth) {
        throw Error(pattern + ": a frame number wider than " + std::to_string(kMaxWidth) +
                    " digits");
      }
      ++j;
    }
    if (j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i')) {
      throw Error(pattern + ": '" + pattern.substr(i, j + 1 - i) +
                  "' is not a frame number; use %d or %05d (and %% for a percent sign)");
    }
    conversion.end = j + 1;
    found.push_back(conversion);
    i = j;
  }
  return found;
}

std::string Unescaped(const std::string& text) {
  std::string result;
  for (std::size_t i = 0; i < text.size(); ++i) {
    result += text[i];
    if (text[i] == '%' && i + 1 < text.size() && text[i + 1] == '%') ++i;
  }
  return result;
}

}  // namespace

bool FramePattern::IsPattern(const std::string& path) {
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] != '%') continue;
    if (i + 1 < path.size() && path[i + 1] == '%') {
      ++i;
      continue;
    }
    return true;
  }
  return false;
}

FramePattern::FramePattern(std::string pattern) : pattern_(std::move(pattern)) {
  const std::vector<Conversion> conversions = Conversions(pattern_);
  if (conversions.size() != 1) {
    throw Error(pattern_ + ": a frame sequence needs exactly one frame number such as %05d, not " +
                std::to_string(conversions.size()));
  }
  const Conversion& conversion = conversions[0];
  prefix_ = Unescaped(pattern_.substr(0, conversion.start));
  suffix_ = Unescaped(pattern_.substr(conversion.end));
  width_ = conversion.width;
  zero_pad_ = conversion.zero_pad;
}

std::string FramePattern::Name(std::int64_t number) const {
  char digits[32];
  std::snprintf(digits, sizeof digits, zero_pad_ ? "%0*lld" : "%*lld", width_,
                static_cast<long long>(number));
  return prefix_ + digits + suffix_;
}

}  // namespace urdfsnap::video
