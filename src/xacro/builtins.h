// The global symbols of xacro's expressions: the Python builtins xacro exposes (list, dict, len,
// str, float, int, min, max, round, ... and the `python` namespace), every `math` name directly
// and as `math.*`, and the `xacro` namespace supplied by the caller.
#pragma once

#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "xacro/python_value.h"

namespace urdfsnap::xacro {

using WarnFunction = std::function<void(const std::string&)>;

// Builds the global symbol table. `xacro_members` become the `xacro` namespace; those named in
// `xacro_direct` are also global names that warn (through `warn`) when called, as do `sorted`
// and `range` (which belong to the `python` namespace).
std::unordered_map<std::string, Value> MakeGlobalSymbols(
    const std::vector<std::pair<std::string, Value>>& xacro_members,
    const std::vector<std::string>& xacro_direct, const WarnFunction& warn);

// Python's len(v) (code points for a str).
Int Length(const Value& v);

}  // namespace urdfsnap::xacro
