// CPython 3.11's hash functions (Python/pyhash.c, Objects/longobject.c, floatobject.c,
// tupleobject.c, setobject.c, complexobject.c, rangeobject.c), on Values.
#include "xacro/internal/python_hash.h"

#include <cmath>
#include <cstring>
#include <vector>

#include "xacro/internal/python_iterators.h"
#include "xacro/internal/python_set.h"

namespace urdfsnap::xacro {
namespace {

constexpr int kHashBits = 61;
constexpr uint64_t kModulus = (uint64_t{1} << kHashBits) - 1;  // sys.hash_info.modulus
constexpr uint64_t kHashInf = 314159;
constexpr uint64_t kHashImag = 1000003;

int64_t NotMinusOne(uint64_t h) { return h == ~uint64_t{0} ? -2 : static_cast<int64_t>(h); }

int64_t HashInt(Int v) {
  const bool negative = v < 0;
  unsigned __int128 magnitude = negative ? -static_cast<unsigned __int128>(v) : static_cast<unsigned __int128>(v);
  const uint64_t h = static_cast<uint64_t>(magnitude % kModulus);
  return NotMinusOne(negative ? -h : h);
}

// identity hash: _Py_HashPointer (the address rotated by 4 bits)
int64_t HashPointer(const void* p) {
  const uint64_t y = reinterpret_cast<uintptr_t>(p);
  return NotMinusOne((y >> 4) | (y << 60));
}

uint64_t Rotl(uint64_t x, int b) { return (x << b) | (x >> (64 - b)); }

void SipRound(uint64_t& v0, uint64_t& v1, uint64_t& v2, uint64_t& v3) {
  v0 += v1; v2 += v3;
  v1 = Rotl(v1, 13) ^ v0; v3 = Rotl(v3, 16) ^ v2;
  v0 = Rotl(v0, 32);
  v2 += v1; v0 += v3;
  v1 = Rotl(v1, 17) ^ v2; v3 = Rotl(v3, 21) ^ v0;
  v2 = Rotl(v2, 32);
}

// SipHash-1-3 with the key k0 = k1 = 0, as CPython's pysiphash under PYTHONHASHSEED=0
uint64_t SipHash13(const unsigned char* in, size_t size) {
  uint64_t b = static_cast<uint64_t>(size) << 56;
  uint64_t v0 = 0x736f6d6570736575ULL, v1 = 0x646f72616e646f6dULL;
  uint64_t v2 = 0x6c7967656e657261ULL, v3 = 0x7465646279746573ULL;
  for (; size >= 8; in += 8, size -= 8) {
    uint64_t m = 0;
    for (int k = 7; k >= 0; --k) m = (m << 8) | in[k];
    v3 ^= m;
    SipRound(v0, v1, v2, v3);
    v0 ^= m;
  }
  uint64_t t = 0;
  for (size_t k = size; k-- > 0;) t = (t << 8) | in[k];
  b |= t;
  v3 ^= b;
  SipRound(v0, v1, v2, v3);
  v0 ^= b;
  v2 ^= 0xff;
  SipRound(v0, v1, v2, v3);
  SipRound(v0, v1, v2, v3);
  SipRound(v0, v1, v2, v3);
  return (v0 ^ v1) ^ (v2 ^ v3);
}

// the bytes CPython hashes: the code points in the string's PEP 393 storage (1, 2 or 4 bytes each,
// little-endian, the width set by the largest code point)
int64_t HashStr(const std::string& s) {
  if (s.empty()) return 0;
  std::vector<uint32_t> points;
  uint32_t largest = 0;
  for (size_t k = 0; k < s.size();) {
    const unsigned char c = s[k];
    const int n = c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc0 ? 2 : 1;
    uint32_t cp = n == 1 ? c : (c & (0x7f >> n));
    for (int j = 1; j < n && k + j < s.size(); ++j) cp = (cp << 6) | (static_cast<unsigned char>(s[k + j]) & 0x3f);
    points.push_back(cp);
    largest = std::max(largest, cp);
    k += n;
  }
  const size_t width = largest < 0x100 ? 1 : (largest < 0x10000 ? 2 : 4);
  std::vector<unsigned char> bytes;
  bytes.reserve(points.size() * width);
  for (uint32_t cp : points) {
    for (size_t k = 0; k < width; ++k) bytes.push_back(static_cast<unsigned char>(cp >> (8 * k)));
  }
  return NotMinusOne(SipHash13(bytes.data(), bytes.size()));
}

int64_t HashTuple(const ValueList& items) {
  constexpr uint64_t kPrime1 = 11400714785074694791ULL;
  constexpr uint64_t kPrime2 = 14029467366897019727ULL;
  constexpr uint64_t kPrime5 = 2870177450012600261ULL;
  uint64_t acc = kPrime5;
  for (const Value& item : items) {
    acc += static_cast<uint64_t>(Hash(item)) * kPrime2;
    acc = Rotl(acc, 31);
    acc *= kPrime1;
  }
  acc += items.size() ^ (kPrime5 ^ 3527539UL);
  return acc == ~uint64_t{0} ? 1546275796 : static_cast<int64_t>(acc);
}

uint64_t ShuffleBits(uint64_t h) { return ((h ^ 89869747UL) ^ (h << 16)) * 3644798167UL; }

int64_t HashFrozenSet(const SetTable& table) {
  // the xor of every active entry's shuffled hash (CPython folds in empty and dummy slots and
  // takes them out again, which comes to the same)
  uint64_t hash = 0;
  table.ForEachEntry([&](const Value&, int64_t h) { hash ^= ShuffleBits(static_cast<uint64_t>(h)); });
  hash ^= (static_cast<uint64_t>(table.size()) + 1) * 1927868237UL;
  hash ^= (hash >> 11) ^ (hash >> 25);
  hash = hash * 69069U + 907133923UL;
  return hash == ~uint64_t{0} ? 590923713 : static_cast<int64_t>(hash);
}

}  // namespace

int64_t HashFloat(double v) {
  if (std::isinf(v)) return v > 0 ? kHashInf : -static_cast<int64_t>(kHashInf);
  if (std::isnan(v)) return 0;  // CPython 3.11 hashes a NaN by identity; one NaN is like another here
  int e = 0;
  double m = std::frexp(v, &e);
  int sign = 1;
  if (m < 0) {
    sign = -1;
    m = -m;
  }
  // 28 bits at a time
  uint64_t x = 0;
  while (m != 0.0) {
    x = ((x << 28) & kModulus) | x >> (kHashBits - 28);
    m *= 268435456.0;
    e -= 28;
    const uint64_t y = static_cast<uint64_t>(m);
    m -= static_cast<double>(y);
    x += y;
    if (x >= kModulus) x -= kModulus;
  }
  e = e >= 0 ? e % kHashBits : kHashBits - 1 - ((-1 - e) % kHashBits);
  x = ((x << e) & kModulus) | x >> (kHashBits - e);
  return NotMinusOne(sign < 0 ? -x : x);
}

int64_t Hash(const Value& v) {
  switch (v.type) {
    // CPython 3.11 hashes None by its address, which varies from run to run in its high bits only:
    // this is one of Debian's python3.11's, so sets holding None iterate in its order
    case Value::Type::kNone: return 0x7fccfc05bbe;
    case Value::Type::kBool:
    case Value::Type::kInt: return HashInt(AsInt(v));
    case Value::Type::kFloat: return HashFloat(v.f);
    case Value::Type::kComplex: {
      const uint64_t combined = static_cast<uint64_t>(HashFloat(v.f)) + kHashImag * static_cast<uint64_t>(HashFloat(v.imag));
      return NotMinusOne(combined);
    }
    case Value::Type::kStr: return HashStr(v.s);
    case Value::Type::kTuple: return HashTuple(*v.list);
    case Value::Type::kFrozenSet: return HashFrozenSet(SetOf(v));
    case Value::Type::kRange: {
      // hash((len, start, step)), with None for what the length makes irrelevant
      const ValueList& r = *v.list;
      const Int length = RangeLength(v);
      if (length == 0) return HashTuple({Value::Integer(0), Value::None(), Value::None()});
      if (length == 1) return HashTuple({Value::Integer(1), r[0], Value::None()});
      return HashTuple({Value::Integer(length), r[0], r[2]});
    }
    case Value::Type::kUnion: {
      // hash(frozenset(args))
      Value set = MakeSet(Value::Type::kFrozenSet);
      for (const Value& t : *v.list) SetOf(set).Add(t);
      return Hash(set);
    }
    case Value::Type::kList:
    case Value::Type::kDict:
    case Value::Type::kSet:
    case Value::Type::kSlice: throw EvalError("unhashable type: '" + TypeName(v) + "'");
    case Value::Type::kFunction: return HashPointer(v.fn.get());
    case Value::Type::kModule: return HashPointer(v.dict.get());
    case Value::Type::kScope: return HashPointer(v.scope.get());
    case Value::Type::kBlock: return HashPointer(v.block);
    case Value::Type::kIterator:
    case Value::Type::kType:
    case Value::Type::kInstance: return HashPointer(v.object.get());
  }
  return 0;
}

}  // namespace urdfsnap::xacro
