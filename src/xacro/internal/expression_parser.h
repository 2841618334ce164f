// The syntax tree of a Python expression and the parser that builds it (precedence and
// associativity as in Python's grammar: conditional, or/and/not, chained comparisons, bitwise,
// arithmetic, unary, power, calls/subscripts/attributes, literals and comprehensions).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

// One `for targets in iter if cond...` clause of a comprehension.
struct ComprehensionClause {
  std::vector<std::string> targets;  // one name, or several for tuple unpacking
  bool unpack = false;
  ExprPtr iter;
  std::vector<ExprPtr> conditions;
};

struct Expr {
  enum class Kind {
    kConst,      // constant
    kName,       // name
    kAttr,       // kids[0].name
    kSubscript,  // kids[0][kids[1]]
    kSlice,      // kids[0..2] (nullptr when omitted)
    kCall,       // kids[0](kids[1..]); keywords holds the names of the trailing keyword arguments
    kUnary,      // op kids[0], op in "-", "+", "~", "not"
    kBinary,     // kids[0] op kids[1]
    kAnd,        // kids[0] and kids[1] and ...
    kOr,
    kCompare,    // kids[0] ops[0] kids[1] ops[1] kids[2] ...
    kIfElse,     // kids[0] if kids[1] else kids[2]
    kList,
    kTuple,
    kDict,       // kids: key, value, key, value, ...
    kSet,        // {kids...}
    kListComp,   // [kids[0] clauses...]
    kSetComp,    // {kids[0] clauses...}
  };
  Kind kind = Kind::kConst;
  Value constant;
  std::string name;  // kName, kAttr; the operator of kUnary/kBinary
  std::vector<ExprPtr> kids;
  std::vector<std::string> ops;       // kCompare operators; kCall keyword names
  std::vector<ComprehensionClause> clauses;
};

// Parses a whole expression; throws EvalError with Python's message on bad syntax and
// "Use of invalid name(s): __x" when any name or attribute starts with a double underscore
// (xacro's guard against reaching Python internals).
ExprPtr ParseExpression(const std::string& text);

}  // namespace urdfsnap::xacro
