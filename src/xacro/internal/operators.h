// Python's operators on values: arithmetic with Python's int/float semantics (true division,
// floor division and modulo with the divisor's sign, exact integer powers), sequence repetition
// and concatenation, `in`, indexing and slicing. Results are bounded in size (evaluation_budget.h).
#pragma once

#include <optional>
#include <string>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// a OP b for OP in + - * / // % ** << >> & | ^.
Value BinaryOp(const std::string& op, const Value& a, const Value& b);

// OP a for OP in - + ~.
Value UnaryOp(const std::string& op, const Value& a);

// Python's `item in container`.
bool Contains(const Value& container, const Value& item);

// v[index] for lists, tuples, strings and dicts (wrapped yaml dicts raise xacro's message).
Value Subscript(const Value& v, const Value& index);

// v[start:stop:step]; nullopt stands for an omitted bound.
Value Slice(const Value& v, std::optional<long> start, std::optional<long> stop, std::optional<long> step);

// slice.indices(length): the slice's start, stop and step clamped to `length` items.
Value SliceIndicesTuple(const Value& slice, Int length);

// The int value of a value used as an index or count (bool or int); EvalError otherwise.
long AsIndex(const Value& v, const char* what);

// Python's int(v) of a number (truncating floats); EvalError for nan/inf.
Int FloatToInt(double v);

}  // namespace urdfsnap::xacro
