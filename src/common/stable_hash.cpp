// StableHash: FNV-1a with the SplitMix64 finalizer, both defined by their published constants.
#include "common/stable_hash.h"

#include <cstdio>

namespace urdfsnap {

std::uint64_t StableHash(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a 64-bit offset basis
  for (const char ch : bytes) {
    h ^= static_cast<unsigned char>(ch);
    h *= 0x100000001b3ULL;  // FNV 64-bit prime
  }
  // SplitMix64's finalizer: every input bit reaches every output bit
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  h ^= h >> 31;
  return h;
}

std::string StableHashText(std::string_view bytes) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(StableHash(bytes)));
  return text;
}

}  // namespace urdfsnap
