// Python's argument checks for builtins, with CPython's own wording, which differs from builtin
// to builtin ("len() takes exactly one argument (2 given)", "set expected at most 1 argument,
// got 2", "int() takes at most 2 arguments (3 given)", "'x' is an invalid keyword argument for
// int()").
#pragma once

#include <string>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// "NAME() takes exactly one argument (N given)"
void TakesOne(const std::string& name, const ValueList& args);

// "NAME expected M arguments, got N", "NAME expected at least M argument(s), got N", "NAME
// expected at most M argument(s), got N"
void Expected(const std::string& name, const ValueList& args, size_t min, size_t max);

// "NAME() takes at most M arguments (N given)"
void TakesAtMost(const std::string& name, const ValueList& args, size_t max);

// "NAME() takes no keyword arguments"
void NoKeywords(const std::string& name, const Kwargs& kwargs);

// "'KEY' is an invalid keyword argument for NAME()" unless every keyword is in `allowed`.
void OnlyKeywords(const std::string& name, const Kwargs& kwargs, const std::vector<std::string>& allowed);

// The keyword argument `key`, or nullptr.
const Value* Keyword(const Kwargs& kwargs, const std::string& key);

}  // namespace urdfsnap::xacro
