// Numbers spelt exactly as Python 3 spells them: repr of floats (shortest round trip, `.0` and
// exponent rules), str of ints, and the int()/float() conversions of text, plus round().
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// Python's repr(float): "0.30000000000000004", "5.0", "1e-05", "1e+16", "inf", "nan", "-0.0".
std::string FormatFloat(double v);

// Python's str(int) for any 128-bit value.
std::string FormatInt(Int v);

// Python's int(text) for base 10: surrounding whitespace, a sign, leading zeros and single
// underscores between digits are accepted; nullopt when Python would raise ValueError (or the
// value needs more than 127 bits).
std::optional<Int> ParseIntText(std::string_view text);

// Python's float(text): whitespace, sign, "inf"/"infinity"/"nan" in any case, ".5", "5.", "1e3".
std::optional<double> ParseFloatText(std::string_view text);

// Python's round(x, ndigits) for a float and ndigits given: correctly rounded, ties to even.
double RoundFloat(double x, long ndigits);

}  // namespace urdfsnap::xacro
