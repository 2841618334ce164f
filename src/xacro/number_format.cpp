// Python 3's spelling of numbers: float repr via the shortest round-trip digits, int str, and the
// text-to-number conversions int() and float() accept.
#include "xacro/internal/number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace urdfsnap::xacro {

std::string FormatFloat(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  // shortest round-trip digits and decimal exponent, e.g. "-1.2345e+02"
  char buf[64];
  auto end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific).ptr;
  std::string sci(buf, end);
  std::string out;
  size_t pos = 0;
  if (sci[0] == '-') {
    out = "-";
    pos = 1;
  }
  const size_t e_pos = sci.find('e');
  std::string digits;
  for (size_t k = pos; k < e_pos; ++k) {
    if (sci[k] != '.') digits += sci[k];
  }
  const int exponent = std::atoi(sci.c_str() + e_pos + 1);
  const int ndigits = static_cast<int>(digits.size());
  const int decpt = exponent + 1;  // digits d1d2... times 10^(decpt - ndigits)
  if (exponent < -4 || exponent >= 16) {
    // Python's repr switches to exponent form outside 1e-4 <= |v| < 1e16
    out += digits[0];
    if (ndigits > 1) out += "." + digits.substr(1);
    char e[16];
    std::snprintf(e, sizeof e, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
    return out + e;
  }
  if (decpt <= 0) return out + "0." + std::string(-decpt, '0') + digits;
  if (decpt >= ndigits) return out + digits + std::string(decpt - ndigits, '0') + ".0";
  return out + digits.substr(0, decpt) + "." + digits.substr(decpt);
}

std::string FormatInt(Int v) {
  if (v == 0) return "0";
  const bool negative = v < 0;
  // work with negative values so that the most negative value does not overflow
  std::string digits;
  Int n = negative ? v : -v;
  while (n != 0) {
    digits += static_cast<char>('0' - static_cast<int>(n % 10));
    n /= 10;
  }
  if (negative) digits += '-';
  return std::string(digits.rbegin(), digits.rend());
}

static std::string_view StripSpace(std::string_view t) {
  const char* ws = " \t\n\r\f\v";
  const size_t b = t.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  return t.substr(b, t.find_last_not_of(ws) - b + 1);
}

std::optional<Int> ParseIntText(std::string_view text) {
  std::string_view t = StripSpace(text);
  bool negative = false;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = t[0] == '-';
    t.remove_prefix(1);
  }
  if (t.empty() || t.front() == '_' || t.back() == '_') return std::nullopt;
  Int value = 0;
  char prev = 0;
  for (char c : t) {
    if (c == '_') {
      if (prev == '_') return std::nullopt;
    } else if (c >= '0' && c <= '9') {
      if (__builtin_mul_overflow(value, 10, &value) || __builtin_add_overflow(value, c - '0', &value)) {
        return std::nullopt;
      }
    } else {
      return std::nullopt;
    }
    prev = c;
  }
  return negative ? -value : value;
}

std::optional<double> ParseFloatText(std::string_view text) {
  const std::string_view t = StripSpace(text);
  if (t.empty()) return std::nullopt;
  std::string lower;
  for (char c : t) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  size_t start = (lower[0] == '+' || lower[0] == '-') ? 1 : 0;
  const std::string body = lower.substr(start);
  const double sign = lower[0] == '-' ? -1.0 : 1.0;
  if (body == "inf" || body == "infinity") return sign * HUGE_VAL;
  if (body == "nan") return std::copysign(NAN, sign);
  // digits with optional '.', at least one digit, optional exponent; underscores between digits
  bool digit_seen = false;
  size_t k = 0;
  std::string clean = lower.substr(0, start);
  auto digits = [&] {
    char prev = 0;
    while (k < body.size() && (std::isdigit(static_cast<unsigned char>(body[k])) || body[k] == '_')) {
      if (body[k] == '_' && (prev == 0 || prev == '_' || k + 1 >= body.size() ||
                             !std::isdigit(static_cast<unsigned char>(body[k + 1])))) {
        return false;
      }
      if (body[k] != '_') {
        clean += body[k];
        digit_seen = true;
      }
      prev = body[k++];
    }
    return true;
  };
  if (!digits()) return std::nullopt;
  if (k < body.size() && body[k] == '.') {
    clean += body[k++];
    if (!digits()) return std::nullopt;
  }
  if (!digit_seen) return std::nullopt;
  if (k < body.size() && body[k] == 'e') {
    clean += body[k++];
    if (k < body.size() && (body[k] == '+' || body[k] == '-')) clean += body[k++];
    digit_seen = false;
    if (!digits() || !digit_seen) return std::nullopt;
  }
  if (k != body.size()) return std::nullopt;
  return std::strtod(clean.c_str(), nullptr);
}

double RoundFloat(double x, long ndigits) {
  if (!std::isfinite(x)) return x;
  if (ndigits > 330) return x;
  if (ndigits < -330) return std::copysign(0.0, x);
  if (ndigits >= 0) {
    // glibc's printf rounds the exact binary value correctly, as Python's dtoa does
    char buf[512];
    std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(ndigits), x);
    return std::strtod(buf, nullptr);
  }
  const double scale = std::pow(10.0, static_cast<double>(-ndigits));
  return std::nearbyint(x / scale) * scale;
}

}  // namespace urdfsnap::xacro
