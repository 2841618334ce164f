// A hash of bytes that is the same on every machine, compiler and run (std::hash is none of these):
// for assigning cases to shards by name and for recognising a suite file in results files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace urdfsnap {

// FNV-1a (64-bit) of `bytes`, then the finalizer of SplitMix64 so that names differing in their
// last character (case_001, case_002) spread over all bits, low ones included. Documented in the
// README so that other tools can reproduce the shard assignment.
std::uint64_t StableHash(std::string_view bytes);

// StableHash as 16 lower-case hex digits.
std::string StableHashText(std::string_view bytes);

}  // namespace urdfsnap
