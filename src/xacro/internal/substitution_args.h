// xacro's `$(...)` substitutions (roslaunch substitution args): $(arg NAME), $(env VAR),
// $(optenv VAR default words), $(find PKG), $(eval EXPR), $(cwd); $(dirname) is refused as the
// reference refuses it.
#pragma once

#include <map>
#include <string>
#include <unordered_map>

#include "common/package_finder.h"
#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

struct SubstitutionContext {
  std::map<std::string, std::string> args;                // xacro:arg values and NAME:=VALUE words
  PackageSearch packages;                                 // for $(find)
  const std::unordered_map<std::string, Value>* globals;  // math names for $(eval)
};

// Resolves one `$(...)` text (the whole substitution, e.g. "$(arg width)") to its string.
// Throws EvalError ("Undefined substitution argument NAME", "environment variable 'V' is not
// set", "Unknown substitution command [...]", ...).
std::string ResolveSubstitution(const std::string& text, const SubstitutionContext& context);

}  // namespace urdfsnap::xacro
