// Complex arithmetic, spelling and parsing as CPython 3.11 has them.
#include "xacro/internal/python_complex.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "xacro/internal/number_format.h"

namespace urdfsnap::xacro {
namespace {

struct C {
  double re, im;
};

[[noreturn]] void Unsupported(const std::string& op, const Value& a, const Value& b) {
  throw EvalError("unsupported operand type(s) for " + op + ": '" + TypeName(a) + "' and '" + TypeName(b) + "'");
}

C ToC(const Value& v) {
  if (v.type == Value::Type::kComplex) return {v.f, v.imag};
  return {AsDouble(v), 0.0};
}

C Prod(C a, C b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }

// Smith's algorithm (CPython's _Py_c_quot); nullopt for a zero divisor
std::optional<C> Quot(C a, C b) {
  const double abs_re = std::fabs(b.re), abs_im = std::fabs(b.im);
  if (abs_re >= abs_im) {
    if (abs_re == 0.0) return std::nullopt;
    const double ratio = b.im / b.re;
    const double denom = b.re + b.im * ratio;
    return C{(a.re + a.im * ratio) / denom, (a.im - a.re * ratio) / denom};
  }
  if (abs_im >= abs_re) {
    const double ratio = b.re / b.im;
    const double denom = b.re * ratio + b.im;
    return C{(a.re * ratio + a.im) / denom, (a.im * ratio - a.re) / denom};
  }
  return C{NAN, NAN};  // a NaN part
}

C PowUnsigned(C x, long n) {
  C r{1.0, 0.0}, p = x;
  for (long mask = 1; mask > 0 && n >= mask; mask <<= 1) {
    if (n & mask) r = Prod(r, p);
    p = Prod(p, p);
  }
  return r;
}

Value Power(C a, C b) {
  bool zero_division = false;
  C p{};
  if (b.im == 0.0 && b.re == std::floor(b.re) && std::fabs(b.re) <= 100.0) {
    // a small integer exponent: repeated squaring, more accurate than the polar form
    const long n = static_cast<long>(b.re);
    if (n > 0) {
      p = PowUnsigned(a, n);
    } else {
      const std::optional<C> q = Quot(C{1.0, 0.0}, PowUnsigned(a, -n));
      zero_division = !q;
      p = q.value_or(C{0.0, 0.0});
    }
  } else if (b.re == 0.0 && b.im == 0.0) {
    p = {1.0, 0.0};
  } else if (a.re == 0.0 && a.im == 0.0) {
    zero_division = b.im != 0.0 || b.re < 0.0;
    p = {0.0, 0.0};
  } else {
    const double vabs = std::hypot(a.re, a.im);
    double len = std::pow(vabs, b.re);
    const double at = std::atan2(a.im, a.re);
    double phase = at * b.re;
    if (b.im != 0.0) {
      len /= std::exp(at * b.im);
      phase += b.im * std::log(vabs);
    }
    p = {len * std::cos(phase), len * std::sin(phase)};
  }
  if (zero_division) throw EvalError("0.0 to a negative or complex power");
  if (std::isinf(p.re) || std::isinf(p.im)) throw EvalError("complex exponentiation");
  return Value::Complex(p.re, p.im);
}

// the repr of one part: repr(float) without the ".0" it adds to integral values
std::string Part(double v) {
  std::string s = FormatFloat(v);
  if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
  return s;
}

// the longest prefix of `s` from `k` that Python's float() reads (sign, digits, point, exponent,
// inf/infinity/nan); returns its end, or k when there is none
size_t FloatPrefix(std::string_view s, size_t k, double& value) {
  size_t j = k;
  if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
  auto word = [&](std::string_view w) {
    if (s.size() - j < w.size()) return false;
    for (size_t n = 0; n < w.size(); ++n) {
      if (std::tolower(static_cast<unsigned char>(s[j + n])) != w[n]) return false;
    }
    return true;
  };
  size_t end = k;
  if (word("infinity")) {
    end = j + 8;
  } else if (word("inf") || word("nan")) {
    end = j + 3;
  } else {
    size_t d = j, digits = 0;
    while (d < s.size() && std::isdigit(static_cast<unsigned char>(s[d]))) ++d, ++digits;
    if (d < s.size() && s[d] == '.') {
      ++d;
      while (d < s.size() && std::isdigit(static_cast<unsigned char>(s[d]))) ++d, ++digits;
    }
    if (digits == 0) return k;
    end = d;
    if (d < s.size() && (s[d] == 'e' || s[d] == 'E')) {
      size_t e = d + 1;
      if (e < s.size() && (s[e] == '+' || s[e] == '-')) ++e;
      const size_t first = e;
      while (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) ++e;
      if (e > first) end = e;
    }
  }
  value = ParseFloatText(s.substr(k, end - k)).value_or(NAN);
  return end;
}

}  // namespace

Value ComplexArith(const std::string& op, const Value& a, const Value& b) {
  const C x = ToC(a), y = ToC(b);
  if (op == "+") return Value::Complex(x.re + y.re, x.im + y.im);
  if (op == "-") return Value::Complex(x.re - y.re, x.im - y.im);
  if (op == "*") {
    const C p = Prod(x, y);
    return Value::Complex(p.re, p.im);
  }
  if (op == "/") {
    const std::optional<C> q = Quot(x, y);
    if (!q) throw EvalError("complex division by zero");
    return Value::Complex(q->re, q->im);
  }
  if (op == "**") return Power(x, y);
  Unsupported(op, a, b);
}

Value FloatPower(double x, double y) {
  // CPython's float_pow: the special cases first, then the platform's pow
  if (y == 0) return Value::Float(1.0);
  if (std::isnan(x)) return Value::Float(x);
  if (std::isnan(y)) return Value::Float(x == 1.0 ? 1.0 : y);
  const auto odd_integer = [](double w) { return std::fmod(std::fabs(w), 2.0) == 1.0; };
  if (std::isinf(y)) {
    const double ax = std::fabs(x);
    if (ax == 1.0) return Value::Float(1.0);
    return Value::Float((y > 0.0) == (ax > 1.0) ? std::fabs(y) : 0.0);
  }
  if (std::isinf(x)) {
    if (y > 0.0) return Value::Float(odd_integer(y) ? x : std::fabs(x));
    return Value::Float(odd_integer(y) ? std::copysign(0.0, x) : 0.0);
  }
  if (x == 0.0) {
    if (y < 0.0) throw EvalError("0.0 cannot be raised to a negative power");
    return Value::Float(odd_integer(y) ? x : 0.0);
  }
  bool negate = false;
  if (x < 0.0) {
    if (y != std::floor(y)) return Power(C{x, 0.0}, C{y, 0.0});  // a complex result
    x = -x;
    negate = odd_integer(y);
  }
  if (x == 1.0) return Value::Float(negate ? -1.0 : 1.0);
  const double r = std::pow(x, y);
  if (std::isinf(r)) throw EvalError("(34, 'Numerical result out of range')");
  return Value::Float(negate ? -r : r);
}

std::string FormatComplex(double real, double imag) {
  if (real == 0.0 && !std::signbit(real)) return Part(imag) + "j";
  std::string im = Part(imag);
  if (im[0] != '-') im = "+" + im;
  return "(" + Part(real) + im + "j)";
}

std::pair<double, double> ParseComplexText(std::string_view text) {
  // underscores are allowed between digits only, and then dropped
  std::string s;
  for (size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '_') {
      s += text[k];
      continue;
    }
    const bool between = k > 0 && k + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[k - 1])) &&
                         std::isdigit(static_cast<unsigned char>(text[k + 1]));
    if (!between) throw EvalError("could not convert string to complex: " + Repr(Value::Str(std::string(text))));
  }
  const auto malformed = [] { return EvalError("complex() arg is a malformed string"); };
  const auto space = [&](size_t k) { return k < s.size() && std::isspace(static_cast<unsigned char>(s[k])); };
  size_t k = 0;
  while (space(k)) ++k;
  const bool bracket = k < s.size() && s[k] == '(';
  if (bracket) {
    ++k;
    while (space(k)) ++k;
  }
  double real = 0.0, imag = 0.0, z = 0.0;
  const auto is_j = [&](size_t j) { return j < s.size() && (s[j] == 'j' || s[j] == 'J'); };
  size_t end = FloatPrefix(s, k, z);
  if (end != k) {
    k = end;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) {
      // <float><signed-float>j or <float><sign>j
      real = z;
      end = FloatPrefix(s, k, imag);
      if (end != k) {
        k = end;
      } else {
        imag = s[k] == '+' ? 1.0 : -1.0;
        ++k;
      }
      if (!is_j(k)) throw malformed();
      ++k;
    } else if (is_j(k)) {
      imag = z;
      ++k;
    } else {
      real = z;
    }
  } else {
    // <sign>j or j
    imag = 1.0;
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) imag = s[k++] == '+' ? 1.0 : -1.0;
    if (!is_j(k)) throw malformed();
    ++k;
  }
  while (space(k)) ++k;
  if (bracket) {
    if (k >= s.size() || s[k] != ')') throw malformed();
    ++k;
    while (space(k)) ++k;
  }
  if (k != s.size()) throw malformed();
  return std::make_pair(real, imag);
}

double ComplexAbs(const Value& z) {
  if (std::isinf(z.f) || std::isinf(z.imag)) return HUGE_VAL;
  if (std::isnan(z.f) || std::isnan(z.imag)) return NAN;
  const double r = std::hypot(z.f, z.imag);
  if (std::isinf(r)) throw EvalError("absolute value too large");
  return r;
}

}  // namespace urdfsnap::xacro
