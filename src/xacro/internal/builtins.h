// The global symbols of xacro's expressions, as xacro's create_global_symbols() makes them: the
// Python builtins xacro exposes directly (list, dict, map, len, str, float, int, True, False, min,
// max, round), the `python` namespace with those and abs, all, any, complex, divmod, enumerate,
// filter, frozenset, hash, isinstance, issubclass, ord, repr, reversed, slice, set, sum, tuple,
// type, zip, sorted and range (the last two also directly, with a deprecation warning), every
// `math` name directly and as `math.*`, and the `xacro` namespace supplied by the caller.
#pragma once

#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

using WarnFunction = std::function<void(const std::string&)>;

// Builds the global symbol table. `xacro_members` become the `xacro` namespace; those named in
// `xacro_direct` are also global names that warn (through `warn`) when called, as do `sorted`
// and `range` (which belong to the `python` namespace).
std::unordered_map<std::string, Value> MakeGlobalSymbols(
    const std::vector<std::pair<std::string, Value>>& xacro_members,
    const std::vector<std::string>& xacro_direct, const WarnFunction& warn);

// Python's len(v) (code points for a str); EvalError "object of type 'int' has no len()".
Int Length(const Value& v);

}  // namespace urdfsnap::xacro
