// Evaluates a parsed Python expression with Python's semantics; names come from a NameLookup
// (xacro's property scopes, or the arguments of $(eval ...)).
#pragma once

#include <string>

#include "xacro/internal/expression_parser.h"
#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

class NameLookup {
 public:
  virtual ~NameLookup() = default;
  // The value of `name`; throws EvalError("name 'x' is not defined") when there is none.
  virtual Value Lookup(const std::string& name) = 0;
};

// Returns the value of `expr`; throws EvalError for Python's runtime errors.
Value Evaluate(const Expr& expr, NameLookup& names);

}  // namespace urdfsnap::xacro
