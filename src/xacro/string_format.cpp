// Python's `%` string formatting on top of C's snprintf for the numeric conversions.
#include "xacro/internal/string_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/operators.h"

namespace urdfsnap::xacro {
namespace {

std::string Pad(std::string body, const std::string& flags, int width) {
  if (static_cast<int>(body.size()) >= width) return body;
  const size_t fill = static_cast<size_t>(width) - body.size();
  if (flags.find('-') != std::string::npos) return body + std::string(fill, ' ');
  return std::string(fill, ' ') + body;
}

std::string FormatNumber(char conv, const std::string& flags, int width, int precision, const Value& v) {
  if (!v.IsNumber()) {
    throw EvalError(std::string("%") + conv + " format: a real number is required, not " + TypeName(v));
  }
  std::string spec = "%" + flags;
  if (width >= 0) spec += std::to_string(width);
  if (conv == 'd' || conv == 'i' || conv == 'u' || conv == 'x' || conv == 'X' || conv == 'o') {
    const Int n = v.type == Value::Type::kFloat ? FloatToInt(v.f) : AsInt(v);
    if (conv != 'x' && conv != 'X' && conv != 'o') {
      // decimal: exact for any 128-bit value
      std::string digits = FormatInt(n < 0 ? -n : n);
      std::string sign = n < 0 ? "-" : (flags.find('+') != std::string::npos ? "+" : (flags.find(' ') != std::string::npos ? " " : ""));
      if (precision > static_cast<int>(digits.size())) digits = std::string(precision - digits.size(), '0') + digits;
      if (flags.find('0') != std::string::npos && flags.find('-') == std::string::npos && width > 0) {
        const int pad = width - static_cast<int>(sign.size() + digits.size());
        if (pad > 0) digits = std::string(pad, '0') + digits;
      }
      return Pad(sign + digits, flags, width);
    }
    spec += std::string("ll") + conv;
    char buf[256];
    std::snprintf(buf, sizeof buf, spec.c_str(), static_cast<long long>(n));
    return buf;
  }
  if (precision >= 0) spec += "." + std::to_string(precision);
  spec += conv;
  const double x = AsDouble(v);
  if (std::isnan(x) || std::isinf(x)) {
    std::string s = std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
    if (conv == 'F' || conv == 'E' || conv == 'G') {
      for (char& c : s) c = static_cast<char>(std::toupper(c));
    }
    return Pad(s, flags, width);
  }
  std::string buf(512, '\0');
  const int n = std::snprintf(buf.data(), buf.size(), spec.c_str(), x);
  if (n >= static_cast<int>(buf.size())) {
    buf.resize(static_cast<size_t>(n) + 1);
    std::snprintf(buf.data(), buf.size(), spec.c_str(), x);
  }
  buf.resize(static_cast<size_t>(n));
  return buf;
}

}  // namespace

std::string PercentFormat(const std::string& format, const Value& args) {
  ValueList positional;
  const bool mapping = args.type == Value::Type::kDict;
  if (args.type == Value::Type::kTuple) {
    positional = *args.list;
  } else {
    positional.push_back(args);
  }
  size_t next = 0;
  auto take = [&]() -> const Value& {
    if (next >= positional.size()) throw EvalError("not enough arguments for format string");
    return positional[next++];
  };
  std::string out;
  // each piece is checked before it is added, so that nothing too large is built
  const auto append = [&out](const std::string& piece) { AppendBounded(out, piece, "formatted string"); };
  for (size_t k = 0; k < format.size(); ++k) {
    if (format[k] != '%') {
      out += format[k];
      continue;
    }
    if (++k >= format.size()) throw EvalError("incomplete format");
    const Value* value = nullptr;
    Value keyed;
    if (format[k] == '(') {
      const size_t close = format.find(')', k);
      if (close == std::string::npos) throw EvalError("incomplete format key");
      if (!mapping) throw EvalError("format requires a mapping");
      keyed = Subscript(args, Value::Str(format.substr(k + 1, close - k - 1)));
      value = &keyed;
      k = close + 1;
    }
    std::string flags;
    while (k < format.size() && std::string("-+ #0").find(format[k]) != std::string::npos) flags += format[k++];
    int width = -1, precision = -1;
    // a width or precision that would make a string over kMaxStringBytes is refused (found by
    // fuzzing: the digits overflowed an int; Python fails as well, with a MemoryError)
    const auto checked = [](long value) {
      if (value > static_cast<long>(kMaxStringBytes) || value < -static_cast<long>(kMaxStringBytes)) {
        throw EvalError("width or precision too big");
      }
      return static_cast<int>(value);
    };
    auto read_number = [&](int& target) {
      if (k < format.size() && format[k] == '*') {
        target = checked(AsIndex(take(), "* width"));
        ++k;
        return;
      }
      if (k < format.size() && std::isdigit(static_cast<unsigned char>(format[k]))) {
        long value = 0;
        while (k < format.size() && std::isdigit(static_cast<unsigned char>(format[k]))) {
          value = std::min(value * 10 + (format[k++] - '0'), static_cast<long>(kMaxStringBytes) + 1);
        }
        target = checked(value);
      }
    };
    read_number(width);
    if (k < format.size() && format[k] == '.') {
      ++k;
      precision = 0;
      read_number(precision);
    }
    while (k < format.size() && (format[k] == 'l' || format[k] == 'h' || format[k] == 'L')) ++k;
    if (k >= format.size()) throw EvalError("incomplete format");
    const char conv = format[k];
    if (conv == '%') {
      out += '%';
      continue;
    }
    if (!value) value = &take();
    switch (conv) {
      case 's':
      case 'r':
      case 'a': {
        std::string s = conv == 's' ? ToStr(*value) : Repr(*value);
        if (precision >= 0 && static_cast<size_t>(precision) < s.size()) s.resize(static_cast<size_t>(precision));
        append(Pad(s, flags, width));
        break;
      }
      case 'c':
        append(Pad(value->type == Value::Type::kStr ? value->s.str() : std::string(1, static_cast<char>(AsInt(*value))), flags, width));
        break;
      case 'd': case 'i': case 'u': case 'x': case 'X': case 'o':
      case 'f': case 'F': case 'e': case 'E': case 'g': case 'G':
        append(FormatNumber(conv, flags, width, precision, *value));
        break;
      default: throw EvalError(std::string("unsupported format character '") + conv + "'");
    }
  }
  if (!mapping && next < positional.size()) throw EvalError("not all arguments converted during string formatting");
  CheckStringSize(out.size(), "formatted string");
  return out;
}

}  // namespace urdfsnap::xacro
