// Python's hash() as 64-bit CPython 3.11 computes it, so that sets iterate in CPython's order and
// hash() prints CPython's numbers: ints and floats modulo 2**61 - 1, tuples by xxHash, frozensets
// by their shuffled-bits xor, complex numbers from both parts, and strings by SipHash-1-3 with the
// key Python uses under PYTHONHASHSEED=0 (xacro's own string hashes change from run to run).
#pragma once

#include <cstdint>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// Python's hash(v); throws EvalError("unhashable type: 'list'") for lists, dicts, sets and slices
// (and tuples holding them). Values without a value-based hash (types, functions, None, NaN) hash
// by identity, as CPython does, so their hashes are stable within one run only.
int64_t Hash(const Value& v);

// Python's hash of a float (also of an int-valued float and of each part of a complex number).
int64_t HashFloat(double v);

}  // namespace urdfsnap::xacro
