// Python's complex numbers: arithmetic as CPython's Objects/complexobject.c does it (Smith's
// division, integer powers by repeated squaring up to 100, polar form beyond, the same
// ZeroDivisionError and OverflowError cases), repr "(1+2j)", and complex('1+2j') parsing.
#pragma once

#include <string>
#include <string_view>
#include <utility>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// a OP b for OP in + - * / ** where one side is complex and the other a number; any other
// operator raises Python's "unsupported operand type(s)" TypeError.
Value ComplexArith(const std::string& op, const Value& a, const Value& b);

// Python's float ** float, which is complex for a negative base and a fractional exponent and an
// OverflowError when the result overflows.
Value FloatPower(double x, double y);

// repr of a complex number: "1j", "(1+2j)", "(-0-1j)", "(nan+infj)".
std::string FormatComplex(double real, double imag);

// complex(text): the real and imaginary parts; EvalError with Python's ValueError message
// ("complex() arg is a malformed string") for text Python does not read.
std::pair<double, double> ParseComplexText(std::string_view text);

// abs(z): hypot of the parts; OverflowError "absolute value too large" when it overflows.
double ComplexAbs(const Value& z);

}  // namespace urdfsnap::xacro
