// Python's math module as xacro exposes it: every name directly and as `math.NAME`.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// The math module's members, name and value.
std::vector<std::pair<std::string, Value>> MathMembers();

// A builtin function of positional arguments only ("NAME() takes no keyword arguments").
Value Fn(const std::string& name, std::function<Value(ValueList&)> body);

}  // namespace urdfsnap::xacro
