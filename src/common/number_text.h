// Numbers to and from text the same way everywhere: locale-independent, shortest round-trip
// output, strict input; and sizes rounded for people.
#pragma once

#include <string>
#include <string_view>

namespace urdfsnap {

// Parses exactly `count` whitespace-separated finite numbers from `text` into `out` (which may be
// null to only check them). An optional leading '+' is accepted. Returns false on anything else.
bool ParseNumbers(std::string_view text, int count, double* out);

// Parses one finite number that fills all of `text`.
bool ParseNumber(std::string_view text, double& out);

// The shortest text that reads back as `value` ("0.5", "-3.14", "1e-07").
std::string FormatNumber(double value);

// A file size for people, in SI units to two or three significant digits: "512 bytes", "834 kB",
// "1.2 MB", "12 MB", "3.4 GB".
std::string FormatBytes(unsigned long long bytes);

}  // namespace urdfsnap
