// Python builtins and the math module, implemented on Value.
#include "xacro/builtins.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "xacro/attributes.h"
#include "xacro/evaluation_budget.h"
#include "xacro/number_format.h"
#include "xacro/operators.h"

namespace urdfsnap::xacro {
namespace {

using Members = std::vector<std::pair<std::string, Value>>;

Value Fn(const std::string& name, std::function<Value(ValueList&)> body) {
  return Value::Callable(name, [name, body = std::move(body)](ValueList& args, Kwargs& kwargs) {
    if (!kwargs.empty()) throw EvalError(name + "() takes no keyword arguments");
    return body(args);
  });
}

double Real(const std::string& function, const Value& v) {
  if (!v.IsNumber()) throw EvalError(function + "(): must be real number, not " + TypeName(v));
  return AsDouble(v);
}

Value Math1(const std::string& name, double (*f)(double)) {
  return Fn(name, [name, f](ValueList& a) {
    CheckArity(name, a, 1, 1);
    const double r = f(Real(name, a[0]));
    if (std::isnan(r) && !std::isnan(AsDouble(a[0]))) throw EvalError("math domain error");
    if (std::isinf(r) && std::isfinite(AsDouble(a[0])) && name != "tan") throw EvalError("math range error");
    return Value::Float(r);
  });
}

Value Math2(const std::string& name, double (*f)(double, double)) {
  return Fn(name, [name, f](ValueList& a) {
    CheckArity(name, a, 2, 2);
    const double r = f(Real(name, a[0]), Real(name, a[1]));
    if (std::isnan(r) && !std::isnan(AsDouble(a[0])) && !std::isnan(AsDouble(a[1]))) throw EvalError("math domain error");
    return Value::Float(r);
  });
}

Value IntResult(const std::string& name, double (*f)(double)) {
  return Fn(name, [name, f](ValueList& a) {
    CheckArity(name, a, 1, 1);
    if (a[0].IsIntLike()) return Value::Integer(AsInt(a[0]));
    return Value::Integer(FloatToInt(f(Real(name, a[0]))));
  });
}

Int IntArg(const std::string& function, const Value& v) {
  if (!v.IsIntLike()) throw EvalError("'" + TypeName(v) + "' object cannot be interpreted as an integer (" + function + ")");
  return AsInt(v);
}

Members MathMembers() {
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
      {"atan2", Math2("atan2", std::atan2)}, {"hypot", Math2("hypot", std::hypot)},
      {"copysign", Math2("copysign", std::copysign)}, {"fmod", Math2("fmod", std::fmod)},
      {"remainder", Math2("remainder", std::remainder)}, {"pow", Math2("pow", std::pow)},
      {"floor", IntResult("floor", std::floor)}, {"ceil", IntResult("ceil", std::ceil)},
      {"trunc", IntResult("trunc", std::trunc)},
      {"degrees", Fn("degrees", [](ValueList& a) { CheckArity("degrees", a, 1, 1); return Value::Float(Real("degrees", a[0]) * (180.0 / M_PI)); })},
      {"radians", Fn("radians", [](ValueList& a) { CheckArity("radians", a, 1, 1); return Value::Float(Real("radians", a[0]) * (M_PI / 180.0)); })},
      {"isnan", Fn("isnan", [](ValueList& a) { CheckArity("isnan", a, 1, 1); return Value::Bool(std::isnan(Real("isnan", a[0]))); })},
      {"isinf", Fn("isinf", [](ValueList& a) { CheckArity("isinf", a, 1, 1); return Value::Bool(std::isinf(Real("isinf", a[0]))); })},
      {"isfinite", Fn("isfinite", [](ValueList& a) { CheckArity("isfinite", a, 1, 1); return Value::Bool(std::isfinite(Real("isfinite", a[0]))); })},
      {"log", Fn("log", [](ValueList& a) {
         CheckArity("log", a, 1, 2);
         const double x = Real("log", a[0]);
         if (x <= 0) throw EvalError("math domain error");
         if (a.size() == 1) return Value::Float(std::log(x));
         const double base = Real("log", a[1]);
         if (base <= 0 || base == 1) throw EvalError("math domain error");
         return Value::Float(std::log(x) / std::log(base));
       })},
      {"isclose", Value::Callable("isclose", [](ValueList& a, Kwargs& kw) {
         CheckArity("isclose", a, 2, 2);
         double rel = 1e-9, abs_tol = 0.0;
         for (auto& [k, v] : kw) {
           if (k == "rel_tol") rel = Real("isclose", v);
           else if (k == "abs_tol") abs_tol = Real("isclose", v);
           else throw EvalError("isclose() got an unexpected keyword argument '" + k + "'");
         }
         const double x = Real("isclose", a[0]), y = Real("isclose", a[1]);
         if (x == y) return Value::Bool(true);
         const double diff = std::fabs(x - y);
         return Value::Bool(diff <= std::fabs(rel * y) || diff <= std::fabs(rel * x) || diff <= abs_tol);
       })},
      {"factorial", Fn("factorial", [](ValueList& a) {
         CheckArity("factorial", a, 1, 1);
         const Int n = IntArg("factorial", a[0]);
         if (n < 0) throw EvalError("factorial() not defined for negative values");
         Value r = Value::Integer(1);
         for (Int k = 2; k <= n; ++k) r = BinaryOp("*", r, Value::Integer(k));
         return r;
       })},
      {"gcd", Fn("gcd", [](ValueList& a) {
         Int g = 0;
         for (const Value& v : a) {
           Int x = IntArg("gcd", v);
           x = x < 0 ? -x : x;
           while (x) { Int t = g % x; g = x; x = t; }
         }
         return Value::Integer(g < 0 ? -g : g);
       })},
      {"isqrt", Fn("isqrt", [](ValueList& a) {
         CheckArity("isqrt", a, 1, 1);
         const Int n = IntArg("isqrt", a[0]);
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
           const double x = Real("fsum", v);
           const double t = sum + x;
           c += std::fabs(sum) >= std::fabs(x) ? (sum - t) + x : (x - t) + sum;
           sum = t;
         }
         return Value::Float(sum + c);
       })},
      {"modf", Fn("modf", [](ValueList& a) {
         CheckArity("modf", a, 1, 1);
         double ip;
         const double fp = std::modf(Real("modf", a[0]), &ip);
         return Value::Tuple({Value::Float(fp), Value::Float(ip)});
       })},
      {"ldexp", Fn("ldexp", [](ValueList& a) {
         CheckArity("ldexp", a, 2, 2);
         return Value::Float(std::ldexp(Real("ldexp", a[0]), static_cast<int>(IntArg("ldexp", a[1]))));
       })},
  };
  return m;
}

ValueList Args1Iterable(const std::string& name, ValueList& a) {
  if (a.empty()) throw EvalError(name + " expected at least 1 argument, got 0");
  return a.size() == 1 ? Iterate(a[0]) : a;
}

Value MinMax(const std::string& name, ValueList& a, Kwargs& kw) {
  ValueList items = Args1Iterable(name, a);
  const Value* dflt = nullptr;
  for (auto& [k, v] : kw) {
    if (k == "default") dflt = &v;
    else throw EvalError(name + "() got an unexpected keyword argument '" + k + "'");
  }
  if (items.empty()) {
    if (dflt) return *dflt;
    throw EvalError(name + "() arg is an empty sequence");
  }
  size_t best = 0;
  for (size_t k = 1; k < items.size(); ++k) {
    const int c = Compare(items[k], items[best], name == "min" ? "<" : ">");
    if (name == "min" ? c < 0 : c > 0) best = k;
  }
  return items[best];
}

Value ToInt(ValueList& a, Kwargs& kw) {
  if (a.empty()) return Value::Integer(0);
  const Value& v = a[0];
  int base = 10;
  if (a.size() > 1) base = static_cast<int>(AsIndex(a[1], "base"));
  for (auto& [k, value] : kw) {
    if (k == "base") base = static_cast<int>(AsIndex(value, "base"));
  }
  if (v.type == Value::Type::kStr) {
    if (base == 10) {
      if (auto i = ParseIntText(v.s)) return Value::Integer(*i);
    } else {
      std::string t = v.s;
      t.erase(std::remove(t.begin(), t.end(), '_'), t.end());
      char* end = nullptr;
      const long long r = std::strtoll(t.c_str(), &end, base);
      if (!t.empty() && end && *end == '\0') return Value::Integer(r);
    }
    throw EvalError("invalid literal for int() with base " + std::to_string(base) + ": " + Repr(v));
  }
  if (v.type == Value::Type::kFloat) return Value::Integer(FloatToInt(v.f));
  if (v.IsIntLike()) return Value::Integer(AsInt(v));
  throw EvalError("int() argument must be a string, a bytes-like object or a real number, not '" + TypeName(v) + "'");
}

Value ToFloat(ValueList& a) {
  CheckArity("float", a, 0, 1);
  if (a.empty()) return Value::Float(0.0);
  const Value& v = a[0];
  if (v.IsNumber()) return Value::Float(AsDouble(v));
  if (v.type == Value::Type::kStr) {
    if (auto f = ParseFloatText(v.s)) return Value::Float(*f);
    throw EvalError("could not convert string to float: " + Repr(v));
  }
  throw EvalError("float() argument must be a string or a real number, not '" + TypeName(v) + "'");
}

Value ToDict(ValueList& a, Kwargs& kw) {
  CheckArity("dict", a, 0, 1);
  std::vector<std::pair<Value, Value>> items;
  auto put = [&items](const Value& key, const Value& value) { DictPut(items, key, value); };
  if (!a.empty()) {
    if (a[0].type == Value::Type::kDict) {
      for (const auto& kv : a[0].dict->items) put(kv.first, kv.second);
    } else {
      for (const Value& pair : Iterate(a[0])) {
        const ValueList kv = Iterate(pair);
        if (kv.size() != 2) throw EvalError("dictionary update sequence element has length " + std::to_string(kv.size()) + "; 2 is required");
        put(kv[0], kv[1]);
      }
    }
  }
  for (auto& [k, v] : kw) put(Value::Str(k), v);
  return Value::Dict(std::move(items));
}

Value Round(ValueList& a, Kwargs& kw) {
  Value ndigits = a.size() > 1 ? a[1] : Value::None();
  for (auto& [k, v] : kw) {
    if (k == "ndigits") ndigits = v;
    else throw EvalError("round() got an unexpected keyword argument '" + k + "'");
  }
  CheckArity("round", a, 1, 2);
  const Value& x = a[0];
  if (!x.IsNumber()) throw EvalError("type " + TypeName(x) + " doesn't define __round__ method");
  if (ndigits.type == Value::Type::kNone) {
    if (x.IsIntLike()) return Value::Integer(AsInt(x));
    return Value::Integer(FloatToInt(std::nearbyint(x.f)));
  }
  const long n = AsIndex(ndigits, "ndigits");
  if (x.IsIntLike()) {
    if (n >= 0) return Value::Integer(AsInt(x));
    return Value::Integer(FloatToInt(RoundFloat(static_cast<double>(AsInt(x)), n)));
  }
  return Value::Float(RoundFloat(x.f, n));
}

Value Sorted(ValueList& a, Kwargs& kw) {
  CheckArity("sorted", a, 1, 1);
  bool reverse = false;
  for (auto& [k, v] : kw) {
    if (k == "reverse") reverse = Truthy(v);
    else throw EvalError("sorted() got an unsupported keyword argument '" + k + "'");
  }
  ValueList items = Iterate(a[0]);
  std::stable_sort(items.begin(), items.end(), [](const Value& x, const Value& y) { return Compare(x, y) < 0; });
  if (reverse) std::reverse(items.begin(), items.end());
  return Value::List(std::move(items));
}

Value Range(ValueList& a) {
  CheckArity("range", a, 1, 3);
  Int start = 0, stop, step = 1;
  if (a.size() == 1) {
    stop = IntArg("range", a[0]);
  } else {
    start = IntArg("range", a[0]);
    stop = IntArg("range", a[1]);
    if (a.size() == 3) step = IntArg("range", a[2]);
  }
  if (step == 0) throw EvalError("range() arg 3 must not be zero");
  // the length is known before anything is built, so a huge range costs nothing to refuse
  // (found by fuzzing: a filtered comprehension over range(10**28) allocated gigabytes first)
  Int span = 0;
  const bool overflow = step > 0 ? __builtin_sub_overflow(stop, start, &span)
                                 : __builtin_sub_overflow(start, stop, &span);
  const Int stride = step > 0 ? step : -step;
  const Int count = span <= 0 ? 0 : (span - 1) / stride + 1;
  if (overflow) throw EvalError("range() too large: its length does not fit in 127 bits");
  CheckListSize(count, "range()");
  ValueList out;
  out.reserve(static_cast<size_t>(count));
  for (Int k = 0; k < count; ++k) out.push_back(Value::Integer(start + k * step));
  return Value::List(std::move(out));
}

Value CallFunction(const Value& f, ValueList args) {
  if (f.type != Value::Type::kFunction) throw EvalError("'" + TypeName(f) + "' object is not callable");
  Kwargs none;
  return f.fn->call(args, none);
}

Value Map(ValueList& a) {
  if (a.size() < 2) throw EvalError("map() must have at least two arguments.");
  std::vector<ValueList> its;
  for (size_t k = 1; k < a.size(); ++k) its.push_back(Iterate(a[k]));
  size_t n = its[0].size();
  for (auto& it : its) n = std::min(n, it.size());
  ValueList out;
  for (size_t k = 0; k < n; ++k) {
    ValueList call_args;
    for (auto& it : its) call_args.push_back(it[k]);
    out.push_back(CallFunction(a[0], std::move(call_args)));
  }
  return Value::List(std::move(out));
}

Value Filter(ValueList& a) {
  CheckArity("filter", a, 2, 2);
  ValueList out;
  for (const Value& v : Iterate(a[1])) {
    const bool keep = a[0].type == Value::Type::kNone ? Truthy(v) : Truthy(CallFunction(a[0], {v}));
    if (keep) out.push_back(v);
  }
  return Value::List(std::move(out));
}

Value Sum(ValueList& a) {
  CheckArity("sum", a, 1, 2);
  Value total = a.size() > 1 ? a[1] : Value::Integer(0);
  for (const Value& v : Iterate(a[0])) total = BinaryOp("+", total, v);
  return total;
}

Value Enumerate(ValueList& a, Kwargs& kw) {
  CheckArity("enumerate", a, 1, 2);
  Int k = a.size() > 1 ? IntArg("enumerate", a[1]) : 0;
  for (auto& [key, v] : kw) {
    if (key == "start") k = IntArg("enumerate", v);
  }
  ValueList out;
  for (const Value& v : Iterate(a[0])) out.push_back(Value::Tuple({Value::Integer(k++), v}));
  return Value::List(std::move(out));
}

Value Zip(ValueList& a) {
  std::vector<ValueList> its;
  for (const Value& v : a) its.push_back(Iterate(v));
  size_t n = its.empty() ? 0 : its[0].size();
  for (auto& it : its) n = std::min(n, it.size());
  ValueList out;
  for (size_t k = 0; k < n; ++k) {
    ValueList row;
    for (auto& it : its) row.push_back(it[k]);
    out.push_back(Value::Tuple(std::move(row)));
  }
  return Value::List(std::move(out));
}

Members BuiltinMembers() {
  return {
      {"list", Fn("list", [](ValueList& a) { CheckArity("list", a, 0, 1); return Value::List(a.empty() ? ValueList{} : Iterate(a[0])); })},
      {"tuple", Fn("tuple", [](ValueList& a) { CheckArity("tuple", a, 0, 1); return Value::Tuple(a.empty() ? ValueList{} : Iterate(a[0])); })},
      {"dict", Value::Callable("dict", ToDict)},
      {"map", Fn("map", Map)},
      {"len", Fn("len", [](ValueList& a) { CheckArity("len", a, 1, 1); return Value::Integer(Length(a[0])); })},
      {"str", Fn("str", [](ValueList& a) { CheckArity("str", a, 0, 1); return Value::Str(a.empty() ? "" : ToStr(a[0])); })},
      {"float", Fn("float", ToFloat)},
      {"int", Value::Callable("int", ToInt)},
      {"True", Value::Bool(true)},
      {"False", Value::Bool(false)},
      {"min", Value::Callable("min", [](ValueList& a, Kwargs& kw) { return MinMax("min", a, kw); })},
      {"max", Value::Callable("max", [](ValueList& a, Kwargs& kw) { return MinMax("max", a, kw); })},
      {"round", Value::Callable("round", Round)},
  };
}

Members PythonOnlyMembers() {
  return {
      {"abs", Fn("abs", [](ValueList& a) {
         CheckArity("abs", a, 1, 1);
         if (a[0].type == Value::Type::kFloat) return Value::Float(std::fabs(a[0].f));
         if (!a[0].IsIntLike()) throw EvalError("bad operand type for abs(): '" + TypeName(a[0]) + "'");
         return AsInt(a[0]) < 0 ? UnaryOp("-", a[0]) : Value::Integer(AsInt(a[0]));
       })},
      {"all", Fn("all", [](ValueList& a) {
         CheckArity("all", a, 1, 1);
         for (const Value& v : Iterate(a[0])) if (!Truthy(v)) return Value::Bool(false);
         return Value::Bool(true);
       })},
      {"any", Fn("any", [](ValueList& a) {
         CheckArity("any", a, 1, 1);
         for (const Value& v : Iterate(a[0])) if (Truthy(v)) return Value::Bool(true);
         return Value::Bool(false);
       })},
      {"divmod", Fn("divmod", [](ValueList& a) {
         CheckArity("divmod", a, 2, 2);
         return Value::Tuple({BinaryOp("//", a[0], a[1]), BinaryOp("%", a[0], a[1])});
       })},
      {"enumerate", Value::Callable("enumerate", Enumerate)},
      {"filter", Fn("filter", Filter)},
      {"ord", Fn("ord", [](ValueList& a) {
         CheckArity("ord", a, 1, 1);
         const std::string& s = StrArg("ord", a, 0);
         if (Length(a[0]) != 1) throw EvalError("ord() expected a character");
         unsigned long cp = static_cast<unsigned char>(s[0]);
         if (s.size() > 1) {
           const int extra = static_cast<int>(s.size()) - 1;
           cp &= 0x3fu >> extra;
           for (int k = 1; k <= extra; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[k]) & 0x3f);
         }
         return Value::Integer(static_cast<Int>(cp));
       })},
      {"repr", Fn("repr", [](ValueList& a) { CheckArity("repr", a, 1, 1); return Value::Str(Repr(a[0])); })},
      {"reversed", Fn("reversed", [](ValueList& a) {
         CheckArity("reversed", a, 1, 1);
         ValueList items = Iterate(a[0]);
         std::reverse(items.begin(), items.end());
         return Value::List(std::move(items));
       })},
      {"sum", Fn("sum", Sum)},
      {"zip", Fn("zip", Zip)},
  };
}

Value Warning(const Value& f, const std::string& message, const WarnFunction& warn) {
  Value g = f;
  g.fn = std::make_shared<Function>(Function{f.fn->name, [f, message, warn](ValueList& a, Kwargs& kw) {
                                               warn(message);
                                               return f.fn->call(a, kw);
                                             }});
  return g;
}

std::vector<std::pair<Value, Value>> Keyed(const Members& members) {
  std::vector<std::pair<Value, Value>> out;
  for (const auto& [name, v] : members) out.emplace_back(Value::Str(name), v);
  return out;
}

}  // namespace

Int Length(const Value& v) {
  switch (v.type) {
    case Value::Type::kStr: {
      Int n = 0;
      for (unsigned char c : v.s) n += (c & 0xc0) != 0x80;
      return n;
    }
    case Value::Type::kList:
    case Value::Type::kTuple: return static_cast<Int>(v.list->size());
    case Value::Type::kDict: return static_cast<Int>(v.dict->items.size());
    default: throw EvalError("object of type '" + TypeName(v) + "' has no len()");
  }
}

std::unordered_map<std::string, Value> MakeGlobalSymbols(const Members& xacro_members,
                                                         const std::vector<std::string>& xacro_direct,
                                                         const WarnFunction& warn) {
  std::unordered_map<std::string, Value> g;
  const Members builtins = BuiltinMembers();
  const Members math = MathMembers();
  Members python = builtins;
  for (auto& m : PythonOnlyMembers()) python.push_back(m);
  const Members deprecated = {{"sorted", Value::Callable("sorted", Sorted)}, {"range", Fn("range", Range)}};
  python.insert(python.end(), deprecated.begin(), deprecated.end());
  for (const auto& [name, v] : builtins) g[name] = v;
  for (const auto& [name, v] : math) g[name] = v;
  for (const auto& [name, v] : deprecated) {
    g[name] = Warning(v, "Using " + name + "() directly is deprecated. Use python." + name + "() instead.", warn);
  }
  for (const auto& [name, v] : xacro_members) {
    if (std::find(xacro_direct.begin(), xacro_direct.end(), name) != xacro_direct.end()) {
      g[name] = Warning(v, "Using " + name + "() directly is deprecated. Use xacro." + name + "() instead.", warn);
    }
  }
  g["python"] = Value::Module("python", Keyed(python));
  g["math"] = Value::Module("math", Keyed(math));
  g["xacro"] = Value::Module("xacro", Keyed(xacro_members));
  return g;
}

}  // namespace urdfsnap::xacro
