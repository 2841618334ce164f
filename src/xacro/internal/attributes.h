// Attribute access on values: members of the math/python/xacro modules, properties of an
// include namespace, keys of yaml dicts, the methods of str, list, tuple, dict, set and
// frozenset, the attributes of numbers, ranges, slices, types and instances of classes.
#pragma once

#include <string>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// Python's `v.name`; a method comes back bound to `v`. Throws EvalError ("'str' object has no
// attribute 'x'", "The yaml dictionary has no key 'x'", ...).
Value GetAttribute(const Value& v, const std::string& name);

// Throws EvalError unless `args` holds between `min` and `max` positional arguments.
void CheckArity(const std::string& function, const ValueList& args, size_t min, size_t max);

// The str argument `index` of `function`; EvalError when it is not a str.
const std::string& StrArg(const std::string& function, const ValueList& args, size_t index);

}  // namespace urdfsnap::xacro
