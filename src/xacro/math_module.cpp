// The math module's functions and constants on Values, with Python's errors.
#include "xacro/internal/math_module.h"

#include <cmath>

#include <algorithm>

#include "xacro/internal/attributes.h"
#include "xacro/internal/call_arguments.h"
#include "xacro/internal/operators.h"

namespace urdfsnap::xacro {
namespace {

using Members = std::vector<std::pair<std::string, Value>>;

double Real(const Value& v) {
  if (!v.IsNumber()) throw EvalError("must be real number, not " + TypeName(v));
  return AsDouble(v);
}

Value Math1(const std::string& name, double (*f)(double)) {
  return Fn(name, [name, f](ValueList& a) {
    CheckArity(name, a, 1, 1);
    const double r = f(Real(a[0]));
    if (std::isnan(r) && !std::isnan(AsDouble(a[0]))) throw EvalError("math domain error");
    if (std::isinf(r) && std::isfinite(AsDouble(a[0])) && name != "tan") throw EvalError("math range error");
    return Value::Float(r);
  });
}

Value Math2(const std::string& name, double (*f)(double, double)) {
  return Fn(name, [name, f](ValueList& a) {
    CheckArity(name, a, 2, 2);
    const double r = f(Real(a[0]), Real(a[1]));
    if (std::isnan(r) && !std::isnan(AsDouble(a[0])) && !std::isnan(AsDouble(a[1]))) throw EvalError("math domain error");
    return Value::Float(r);
  });
}

Value IntResult(const std::string& name, double (*f)(double)) {
  return Fn(name, [name, f](ValueList& a) {
    CheckArity(name, a, 1, 1);
    if (a[0].IsIntLike()) return Value::Integer(AsInt(a[0]));
    return Value::Integer(FloatToInt(f(Real(a[0]))));
  });
}

Int IntArg(const Value& v) {
  if (!v.IsIntLike()) throw EvalError("'" + TypeName(v) + "' object cannot be interpreted as an integer");
  return AsInt(v);
}

// n! / (n - k)!, exactly (an EvalError when it needs more than 127 bits)
Value FallingFactorial(Int n, Int k) {
  Value r = Value::Integer(1);
  for (Int j = 0; j < k; ++j) r = BinaryOp("*", r, Value::Integer(n - j));
  return r;
}

Int Gcd(Int a, Int b) {
  a = a < 0 ? -a : a;
  b = b < 0 ? -b : b;
  while (b) {
    const Int t = a % b;
    a = b;
    b = t;
  }
  return a;
}

// the length of a vector (CPython's vector_norm: inf wins over nan); glibc's correctly rounded
// hypot for two coordinates, extended precision for more
double Norm(const std::vector<double>& v) {
  bool infinite = false, nan = false;
  for (double x : v) {
    infinite = infinite || std::isinf(x);
    nan = nan || std::isnan(x);
  }
  if (infinite) return HUGE_VAL;
  if (nan) return NAN;
  if (v.size() <= 2) return std::hypot(v.empty() ? 0.0 : v[0], v.size() < 2 ? 0.0 : v[1]);
  long double largest = 0.0L, sum = 0.0L;
  for (double x : v) largest = std::max(largest, std::fabs(static_cast<long double>(x)));
  if (largest == 0.0L) return 0.0;
  for (double x : v) {
    const long double scaled = x / largest;
    sum += scaled * scaled;
  }
  return static_cast<double>(largest * std::sqrt(sum));
}

// the math functions on integers and iterables Python 3.8 to 3.11 added
Members NewerMathMembers() {
  return {
      {"comb", Fn("comb", [](ValueList& a) {
         Expected("comb", a, 2, 2);
         const Int n = IntArg(a[0]), k = IntArg(a[1]);
         if (n < 0) throw EvalError("n must be a non-negative integer");
         if (k < 0) throw EvalError("k must be a non-negative integer");
         if (k > n) return Value::Integer(0);
         // C(n, k) = C(n, k - 1) * (n - k + 1) / k, exact at every step
         const Int m = std::min(k, n - k);
         Value r = Value::Integer(1);
         for (Int j = 1; j <= m; ++j) r = BinaryOp("//", BinaryOp("*", r, Value::Integer(n - m + j)), Value::Integer(j));
         return r;
       })},
      {"perm", Fn("perm", [](ValueList& a) {
         Expected("perm", a, 1, 2);
         const Int n = IntArg(a[0]);
         if (a.size() == 1 || a[1].type == Value::Type::kNone) {
           if (n < 0) throw EvalError("factorial() not defined for negative values");
           return FallingFactorial(n, n);
         }
         const Int k = IntArg(a[1]);
         if (n < 0) throw EvalError("n must be a non-negative integer");
         if (k < 0) throw EvalError("k must be a non-negative integer");
         return k > n ? Value::Integer(0) : FallingFactorial(n, k);
       })},
      {"dist", Fn("dist", [](ValueList& a) {
         Expected("dist", a, 2, 2);
         const ValueList p = Iterate(a[0]), q = Iterate(a[1]);
         if (p.size() != q.size()) throw EvalError("both points must have the same number of dimensions");
         std::vector<double> d;
         for (size_t k = 0; k < p.size(); ++k) d.push_back(Real(p[k]) - Real(q[k]));
         return Value::Float(Norm(d));
       })},
      {"frexp", Fn("frexp", [](ValueList& a) {
         CheckArity("frexp", a, 1, 1);
         const double x = Real(a[0]);
         if (!std::isfinite(x)) return Value::Tuple({Value::Float(x), Value::Integer(0)});
         int e = 0;
         const double m = std::frexp(x, &e);
         return Value::Tuple({Value::Float(m), Value::Integer(e)});
       })},
      {"lcm", Fn("lcm", [](ValueList& a) {
         Value r = Value::Integer(1);
         for (const Value& v : a) {
           const Int x = IntArg(v), current = AsInt(r);
           if (x == 0 || current == 0) {
             r = Value::Integer(0);
             continue;
           }
           r = BinaryOp("*", Value::Integer(current / Gcd(current, x)), Value::Integer(x < 0 ? -x : x));
         }
         return r;
       })},
      {"nextafter", Fn("nextafter", [](ValueList& a) {
         Expected("nextafter", a, 2, 2);
         return Value::Float(std::nextafter(Real(a[0]), Real(a[1])));
       })},
      {"prod", Value::Callable("prod", [](ValueList& a, Kwargs& kw) {
         if (a.size() != 1) {
           throw EvalError("prod() takes exactly 1 positional argument (" + std::to_string(a.size()) + " given)");
         }
         OnlyKeywords("prod", kw, {"start"});
         const Value* start = Keyword(kw, "start");
         Value r = start ? *start : Value::Integer(1);
         const NextFunction next = IterateLazily(a[0]);
         while (std::optional<Value> item = next()) r = BinaryOp("*", r, *item);
         return r;
       })},
      {"ulp", Fn("ulp", [](ValueList& a) {
         CheckArity("ulp", a, 1, 1);
         const double x = std::fabs(Real(a[0]));
         if (!std::isfinite(x)) return Value::Float(x);
         const double next = std::nextafter(x, HUGE_VAL);
         return Value::Float(std::isinf(next) ? x - std::nextafter(x, 0.0) : next - x);
       })},
      {"hypot", Fn("hypot", [](ValueList& a) {
         std::vector<double> v;
         for (const Value& x : a) v.push_back(Real(x));
         return Value::Float(Norm(v));
       })},
  };
}

}  // namespace

std::vector<std::pair<std::string, Value>> MathMembers() {
  Members m = {
      {"pi", Value::Float(M_PI)}, {"e", Value::Float(M_E)}, {"tau", Value::Float(2 * M_PI)},
      {"inf", Value::Float(HUGE_VAL)}, {"nan", Value::Float(NAN)},
      {"sin", Math1("sin", std::sin)}, {"cos", Math1("cos", std::cos)}, {"tan", Math1("tan", std::tan)},
      {"asin", Math1("asin", std::asin)}, {"acos", Math1("acos", std::acos)}, {"atan", Math1("atan", std::atan)},
      {"sinh", Math1("sinh", std::sinh)}, {"cosh", Math1("cosh", std::cosh)}, {"tanh", Math1("tanh", std::tanh)},
      {"asinh", Math1("asinh", std::asinh)}, {"acosh", Math1("acosh", std::acosh)}, {"atanh", Math1("atanh", std::atanh)},
      {"exp", Math1("exp", std::exp)}, {"expm1", Math1("expm1", std::expm1)}, {"log1p", Math1("log1p", std::log1p)},
      {"log2", Math1("log2", std::log2)}, {"log10", Math1("log10", std::log10)}, {"sqrt", Math1("sqrt", std::sqrt)},
      {"fabs", Math1("fabs", std::fabs)}, {"erf", Math1("erf", std::erf)}, {"erfc", Math1("erfc", std::erfc)},
      {"gamma", Math1("gamma", std::tgamma)}, {"lgamma", Math1("lgamma", std::lgamma)},
      {"cbrt", Math1("cbrt", std::cbrt)}, {"exp2", Math1("exp2", std::exp2)},
      {"atan2", Math2("atan2", std::atan2)},
      {"copysign", Math2("copysign", std::copysign)}, {"fmod", Math2("fmod", std::fmod)},
      {"remainder", Math2("remainder", std::remainder)}, {"pow", Math2("pow", std::pow)},
      {"floor", IntResult("floor", std::floor)}, {"ceil", IntResult("ceil", std::ceil)},
      {"trunc", IntResult("trunc", std::trunc)},
      {"degrees", Fn("degrees", [](ValueList& a) { CheckArity("degrees", a, 1, 1); return Value::Float(Real(a[0]) * (180.0 / M_PI)); })},
      {"radians", Fn("radians", [](ValueList& a) { CheckArity("radians", a, 1, 1); return Value::Float(Real(a[0]) * (M_PI / 180.0)); })},
      {"isnan", Fn("isnan", [](ValueList& a) { CheckArity("isnan", a, 1, 1); return Value::Bool(std::isnan(Real(a[0]))); })},
      {"isinf", Fn("isinf", [](ValueList& a) { CheckArity("isinf", a, 1, 1); return Value::Bool(std::isinf(Real(a[0]))); })},
      {"isfinite", Fn("isfinite", [](ValueList& a) { CheckArity("isfinite", a, 1, 1); return Value::Bool(std::isfinite(Real(a[0]))); })},
      {"log", Fn("log", [](ValueList& a) {
         CheckArity("log", a, 1, 2);
         const double x = Real(a[0]);
         if (x <= 0) throw EvalError("math domain error");
         if (a.size() == 1) return Value::Float(std::log(x));
         const double base = Real(a[1]);
         if (base <= 0 || base == 1) throw EvalError("math domain error");
         return Value::Float(std::log(x) / std::log(base));
       })},
      {"isclose", Value::Callable("isclose", [](ValueList& a, Kwargs& kw) {
         CheckArity("isclose", a, 2, 2);
         double rel = 1e-9, abs_tol = 0.0;
         for (auto& [k, v] : kw) {
           if (k == "rel_tol") rel = Real(v);
           else if (k == "abs_tol") abs_tol = Real(v);
           else throw EvalError("isclose() got an unexpected keyword argument '" + k + "'");
         }
         const double x = Real(a[0]), y = Real(a[1]);
         if (x == y) return Value::Bool(true);
         const double diff = std::fabs(x - y);
         return Value::Bool(diff <= std::fabs(rel * y) || diff <= std::fabs(rel * x) || diff <= abs_tol);
       })},
      {"factorial", Fn("factorial", [](ValueList& a) {
         CheckArity("factorial", a, 1, 1);
         const Int n = IntArg(a[0]);
         if (n < 0) throw EvalError("factorial() not defined for negative values");
         Value r = Value::Integer(1);
         for (Int k = 2; k <= n; ++k) r = BinaryOp("*", r, Value::Integer(k));
         return r;
       })},
      {"gcd", Fn("gcd", [](ValueList& a) {
         Int g = 0;
         for (const Value& v : a) {
           Int x = IntArg(v);
           x = x < 0 ? -x : x;
           while (x) { Int t = g % x; g = x; x = t; }
         }
         return Value::Integer(g < 0 ? -g : g);
       })},
      {"isqrt", Fn("isqrt", [](ValueList& a) {
         CheckArity("isqrt", a, 1, 1);
         const Int n = IntArg(a[0]);
         if (n < 0) throw EvalError("isqrt() argument must be nonnegative");
         Int r = static_cast<Int>(std::sqrt(static_cast<double>(n)));
         while (r * r > n) --r;
         while ((r + 1) * (r + 1) <= n) ++r;
         return Value::Integer(r);
       })},
      {"fsum", Fn("fsum", [](ValueList& a) {
         CheckArity("fsum", a, 1, 1);
         // Neumaier summation: exact enough for the sums robot descriptions make
         double sum = 0.0, c = 0.0;
         for (const Value& v : Iterate(a[0])) {
           const double x = Real(v);
           const double t = sum + x;
           c += std::fabs(sum) >= std::fabs(x) ? (sum - t) + x : (x - t) + sum;
           sum = t;
         }
         return Value::Float(sum + c);
       })},
      {"modf", Fn("modf", [](ValueList& a) {
         CheckArity("modf", a, 1, 1);
         double ip;
         const double fp = std::modf(Real(a[0]), &ip);
         return Value::Tuple({Value::Float(fp), Value::Float(ip)});
       })},
      {"ldexp", Fn("ldexp", [](ValueList& a) {
         CheckArity("ldexp", a, 2, 2);
         return Value::Float(std::ldexp(Real(a[0]), static_cast<int>(IntArg(a[1]))));
       })},
  };
  for (auto& member : NewerMathMembers()) m.push_back(std::move(member));
  return m;
}

Value Fn(const std::string& name, std::function<Value(ValueList&)> body) {
  return Value::Callable(name, [name, body = std::move(body)](ValueList& args, Kwargs& kwargs) {
    if (!kwargs.empty()) throw EvalError(name + "() takes no keyword arguments");
    return body(args);
  });
}

}  // namespace urdfsnap::xacro
