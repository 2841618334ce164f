// Numbers to and from text the same way everywhere (options, joint values, URDF, .rviz files):
// locale-independent, shortest round-trip output, strict input; and sizes rounded for people.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap {

// Parses exactly `count` whitespace-separated finite numbers from `text` into `out` (which may be
// null to only check them). An optional leading '+' is accepted. Returns false on anything else.
bool ParseNumbers(std::string_view text, int count, double* out);

// Parses one finite number that fills all of `text`.
bool ParseNumber(std::string_view text, double& out);

// Parses one decimal integer that fills all of `text` (no sign '+', no spaces).
bool ParseInteger(std::string_view text, int& out);

// The shortest text that reads back as `value` ("0.5", "-3.14", "1e-07").
std::string FormatNumber(double value);

// A number for people, in messages: rounded to five significant digits (never rounding away
// digits before the decimal point), without trailing zeros or float noise, followed by " UNIT"
// when `unit` is not empty: 0.5999974410156591 → "0.6", (2.8973, "rad") → "2.8973 rad",
// (12345.678, "s") → "12346 s", 1.5e-07 → "1.5e-07".
std::string FormatForPeople(double value, std::string_view unit = "");

// A range for people as the user would type its ends: (-2.9, 2.9, "rad") → "-2.9 to 2.9 rad".
std::string FormatRangeForPeople(double low, double high, std::string_view unit = "");

// A file size for people, in SI units to two or three significant digits: "512 bytes", "834 kB",
// "1.2 MB", "12 MB", "3.4 GB".
std::string FormatBytes(unsigned long long bytes);

}  // namespace urdfsnap
