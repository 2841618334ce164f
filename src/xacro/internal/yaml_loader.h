// xacro.load_yaml: a YAML file as Python values, typed as PyYAML's safe loader types YAML 1.1
// scalars (yes/no/on/off booleans, `1e3` stays text, `1.0e+3` is a float, `~`/null is None),
// with the `!radians EXPR` and `!degrees EXPR` tags; dicts and lists come back wrapped for
// xacro's dotted access (`cfg.robot.name`).
#pragma once

#include <functional>
#include <string>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// Loads `path`. `evaluate` evaluates the text of an angle tag as an expression. Throws EvalError
// with the file and the YAML problem; IoError-like failures say "No such file or directory".
Value LoadYaml(const std::string& path, const std::function<Value(const std::string&)>& evaluate);

// The Python value PyYAML gives an untagged plain scalar.
Value ResolveYamlScalar(const std::string& text);

}  // namespace urdfsnap::xacro
