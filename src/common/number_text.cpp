// Strict number parsing and shortest formatting with std::from_chars / std::to_chars; file sizes
// for people.
#include "common/number_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace urdfsnap {

bool ParseNumbers(std::string_view text, int count, double* out) {
  int parsed = 0;
  size_t i = 0;
  while (true) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i == text.size()) break;
    if (text[i] == '+' && i + 1 < text.size() && text[i + 1] != '-') ++i;
    double value = 0;
    const auto [end, error] = std::from_chars(text.data() + i, text.data() + text.size(), value);
    if (error != std::errc() || !std::isfinite(value) || parsed == count) return false;
    if (out) out[parsed] = value;
    ++parsed;
    i = end - text.data();
    if (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) return false;
  }
  return parsed == count;
}

bool ParseNumber(std::string_view text, double& out) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) ||
      std::isspace(static_cast<unsigned char>(text.back()))) {
    return false;
  }
  return ParseNumbers(text, 1, &out);
}

std::string FormatNumber(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

bool ParseInteger(std::string_view text, int& out) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size() && !text.empty();
}

std::string FormatForPeople(double value, std::string_view unit) {
  constexpr int kSignificant = 5;
  char text[64];
  if (!std::isfinite(value)) {
    std::snprintf(text, sizeof text, "%g", value);
  } else if (std::abs(value) >= 1) {
    const int whole_digits = static_cast<int>(std::floor(std::log10(std::abs(value)))) + 1;
    std::snprintf(text, sizeof text, "%.*f", std::max(0, kSignificant - whole_digits), value);
  } else {
    std::snprintf(text, sizeof text, "%.*g", kSignificant, value);
  }
  std::string number = text;
  if (number.find('.') != std::string::npos && number.find('e') == std::string::npos) {
    number.erase(number.find_last_not_of('0') + 1);
    if (number.back() == '.') number.pop_back();
  }
  if (number == "-0") number = "0";
  return unit.empty() ? number : number + " " + std::string(unit);
}

std::string FormatRangeForPeople(double low, double high, std::string_view unit) {
  return FormatForPeople(low) + " to " + FormatForPeople(high, unit);
}

std::string FormatBytes(unsigned long long bytes) {
  if (bytes < 1000) return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
  const char* units[] = {"kB", "MB", "GB", "TB", "PB"};
  double value = bytes / 1000.0;
  int unit = 0;
  // 999.95 kB would print as "1000 kB": move on to the next unit before it rounds up to 1000
  while (value >= 999.5 && unit < 4) {
    value /= 1000;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, value < 9.95 ? "%.1f %s" : "%.0f %s", value, units[unit]);
  return text;
}

}  // namespace urdfsnap
