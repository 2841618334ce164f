// Splits the text of a Python expression into tokens: names, number and string literals,
// operators and brackets, as Python's tokenizer does for the subset xacro accepts.
#pragma once

#include <string>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

struct Token {
  enum class Kind { kName, kNumber, kString, kOp, kEnd };
  Kind kind = Kind::kEnd;
  std::string text;  // name, operator, or decoded string content
  Value number;      // kNumber: an int or float
};

// Tokenizes `expr`; throws EvalError("invalid syntax", ...) on text Python cannot tokenize.
std::vector<Token> Tokenize(const std::string& expr);

}  // namespace urdfsnap::xacro
