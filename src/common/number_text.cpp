// Strict number parsing and shortest formatting with std::from_chars / std::to_chars.
#include "common/number_text.h"

#include <cctype>
#include <charconv>
#include <cmath>

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

}  // namespace urdfsnap
