// Python's builtin functions on Values (the types are in type_constructors.cpp, math in
// math_module.cpp) and the global symbol table xacro's expressions start from.
#include "xacro/internal/builtins.h"

#include <algorithm>
#include <cmath>

#include "xacro/internal/call_arguments.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/math_module.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/operators.h"
#include "xacro/internal/python_complex.h"
#include "xacro/internal/python_hash.h"
#include "xacro/internal/python_iterators.h"
#include "xacro/internal/python_set.h"
#include "xacro/internal/python_types.h"

namespace urdfsnap::xacro {
namespace {

using Members = std::vector<std::pair<std::string, Value>>;

// CPython's list.sort for a list shorter than 64 items: the leading run, then binary insertion;
// the same order as CPython's timsort even when '<' is not a total order (NaN, sets)
void SmallSort(std::vector<size_t>& order, const ValueList& keys) {
  const auto less = [&](size_t a, size_t b) { return RichCompare("<", keys[a], keys[b]); };
  const size_t n = order.size();
  if (n < 2) return;
  size_t run = 2;
  if (less(order[1], order[0])) {
    while (run < n && less(order[run], order[run - 1])) ++run;
    std::reverse(order.begin(), order.begin() + static_cast<long>(run));
  } else {
    while (run < n && !less(order[run], order[run - 1])) ++run;
  }
  for (size_t start = run; start < n; ++start) {
    const size_t pivot = order[start];
    size_t l = 0, r = start;
    while (l < r) {
      const size_t p = l + ((r - l) >> 1);
      if (less(pivot, order[p])) r = p;
      else l = p + 1;
    }
    std::move_backward(order.begin() + static_cast<long>(l), order.begin() + static_cast<long>(start),
                       order.begin() + static_cast<long>(start) + 1);
    order[l] = pivot;
  }
}

// list.sort(key=..., reverse=...) as CPython does it: keys computed first, a reversed sort made
// stable by reversing before and after
void SortValues(ValueList& items, const Value* key, bool reverse) {
  ValueList keys;
  if (key && key->type != Value::Type::kNone) {
    keys.reserve(items.size());
    for (const Value& item : items) keys.push_back(CallValue(*key, {item}));
  } else {
    keys = items;
  }
  if (reverse) {
    std::reverse(items.begin(), items.end());
    std::reverse(keys.begin(), keys.end());
  }
  std::vector<size_t> order(items.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  if (order.size() < 64) {
    SmallSort(order, keys);
  } else {
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return RichCompare("<", keys[a], keys[b]); });
  }
  ValueList sorted;
  sorted.reserve(items.size());
  for (size_t k : order) sorted.push_back(std::move(items[k]));
  if (reverse) std::reverse(sorted.begin(), sorted.end());
  items = std::move(sorted);
}

Value Sorted(ValueList& a, Kwargs& kw) {
  Expected("sorted", a, 1, 1);
  OnlyKeywords("sort", kw, {"key", "reverse"});
  ValueList items = Iterate(a[0]);
  const Value* reverse = Keyword(kw, "reverse");
  SortValues(items, Keyword(kw, "key"), reverse && Truthy(*reverse));
  return Value::List(std::move(items));
}

Value MinMax(const std::string& name, ValueList& a, Kwargs& kw) {
  if (a.empty()) throw EvalError(name + " expected at least 1 argument, got 0");
  OnlyKeywords(name, kw, {"key", "default"});
  const Value* key = Keyword(kw, "key");
  const Value* dflt = Keyword(kw, "default");
  if (dflt && a.size() > 1) {
    throw EvalError("Cannot specify a default for " + name + "() with multiple positional arguments");
  }
  const NextFunction next = a.size() == 1 ? IterateLazily(a[0]) : IterateLazily(Value::Tuple(a));
  std::optional<Value> best, best_key;
  while (std::optional<Value> item = next()) {
    Value k = key && key->type != Value::Type::kNone ? CallValue(*key, {*item}) : *item;
    if (!best || RichCompare(name == "min" ? "<" : ">", k, *best_key)) {
      best = std::move(item);
      best_key = std::move(k);
    }
  }
  if (best) return *best;
  if (dflt) return *dflt;
  throw EvalError(name + "() arg is an empty sequence");
}

Value Round(ValueList& a, Kwargs& kw) {
  TakesAtMost("round", a, 2);
  OnlyKeywords("round", kw, {"number", "ndigits"});
  const Value* number = a.empty() ? Keyword(kw, "number") : &a[0];
  if (!number) throw EvalError("round() missing required argument 'number' (pos 1)");
  const Value* given = a.size() > 1 ? &a[1] : Keyword(kw, "ndigits");
  const Value ndigits = given ? *given : Value::None();
  const Value& x = *number;
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

Value Sum(ValueList& a, Kwargs& kw) {
  if (a.empty()) throw EvalError("sum() takes at least 1 positional argument (0 given)");
  TakesAtMost("sum", a, 2);
  OnlyKeywords("sum", kw, {"start"});
  const Value* start = a.size() > 1 ? &a[1] : Keyword(kw, "start");
  Value total = start ? *start : Value::Integer(0);
  if (total.type == Value::Type::kStr) throw EvalError("sum() can't sum strings [use ''.join(seq) instead]");
  const NextFunction next = IterateLazily(a[0]);
  while (std::optional<Value> item = next()) total = BinaryOp("+", total, *item);
  return total;
}

Value Abs(const Value& x) {
  if (x.type == Value::Type::kFloat) return Value::Float(std::fabs(x.f));
  if (x.type == Value::Type::kComplex) return Value::Float(ComplexAbs(x));
  if (!x.IsIntLike()) throw EvalError("bad operand type for abs(): '" + TypeName(x) + "'");
  return AsInt(x) < 0 ? UnaryOp("-", x) : Value::Integer(AsInt(x));
}

Value Divmod(const Value& x, const Value& y) {
  if (!x.IsNumber() || !y.IsNumber()) {
    throw EvalError("unsupported operand type(s) for divmod(): '" + TypeName(x) + "' and '" + TypeName(y) + "'");
  }
  if (!(x.IsIntLike() && y.IsIntLike()) && AsDouble(y) == 0.0) throw EvalError("float divmod()");
  return Value::Tuple({BinaryOp("//", x, y), BinaryOp("%", x, y)});
}

Value Ord(const Value& c) {
  if (c.type != Value::Type::kStr) throw EvalError("ord() expected string of length 1, but " + TypeName(c) + " found");
  const Int n = Length(c);
  if (n != 1) throw EvalError("ord() expected a character, but string of length " + FormatInt(n) + " found");
  const std::string& s = c.s;
  unsigned long cp = static_cast<unsigned char>(s[0]);
  if (s.size() > 1) {
    const int extra = static_cast<int>(s.size()) - 1;
    cp &= 0x3fu >> extra;
    for (int k = 1; k <= extra; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[k]) & 0x3f);
  }
  return Value::Integer(static_cast<Int>(cp));
}

// all() and any(): the first item that decides, read lazily
Value AllAny(const Value& iterable, bool want) {
  const NextFunction next = IterateLazily(iterable);
  while (std::optional<Value> item = next()) {
    if (Truthy(*item) == want) return Value::Bool(want);
  }
  return Value::Bool(!want);
}

// a function of exactly one argument with "NAME() takes exactly one argument" wording
Value One(const std::string& name, Value (*body)(const Value&)) {
  return Value::Callable(name, [name, body](ValueList& a, Kwargs& kw) {
    NoKeywords(name, kw);
    TakesOne(name, a);
    return body(a[0]);
  });
}

// a function of exactly two arguments with "NAME expected 2 arguments" wording
Value Two(const std::string& name, Value (*body)(const Value&, const Value&)) {
  return Value::Callable(name, [name, body](ValueList& a, Kwargs& kw) {
    NoKeywords(name, kw);
    Expected(name, a, 2, 2);
    return body(a[0], a[1]);
  });
}

// the builtins xacro exposes directly as well as in `python`
Members DirectBuiltins() {
  return {
      {"list", BuiltinType("list")},
      {"dict", BuiltinType("dict")},
      {"map", BuiltinType("map")},
      {"len", One("len", [](const Value& v) { return Value::Integer(Length(v)); })},
      {"str", BuiltinType("str")},
      {"float", BuiltinType("float")},
      {"int", BuiltinType("int")},
      {"True", Value::Bool(true)},
      {"False", Value::Bool(false)},
      {"min", Value::Callable("min", [](ValueList& a, Kwargs& kw) { return MinMax("min", a, kw); })},
      {"max", Value::Callable("max", [](ValueList& a, Kwargs& kw) { return MinMax("max", a, kw); })},
      {"round", Value::Callable("round", Round)},
  };
}

// the rest of `python`, in xacro's order
Members PythonOnlyBuiltins() {
  return {
      {"abs", One("abs", Abs)},
      {"all", One("all", [](const Value& v) { return AllAny(v, false); })},
      {"any", One("any", [](const Value& v) { return AllAny(v, true); })},
      {"complex", BuiltinType("complex")},
      {"divmod", Two("divmod", Divmod)},
      {"enumerate", BuiltinType("enumerate")},
      {"filter", BuiltinType("filter")},
      {"frozenset", BuiltinType("frozenset")},
      {"hash", One("hash", [](const Value& v) { return Value::Integer(Hash(v)); })},
      {"isinstance", Two("isinstance", [](const Value& v, const Value& c) { return Value::Bool(IsInstance(v, c)); })},
      {"issubclass", Two("issubclass", [](const Value& v, const Value& c) { return Value::Bool(IsSubclass(v, c)); })},
      {"ord", One("ord", Ord)},
      {"repr", One("repr", [](const Value& v) {
         std::string text = Repr(v);
         EvaluationBudget::ChargeBytes(text.size());
         return Value::Str(std::move(text));
       })},
      {"reversed", BuiltinType("reversed")},
      {"slice", BuiltinType("slice")},
      {"set", BuiltinType("set")},
      {"sum", Value::Callable("sum", Sum)},
      {"tuple", BuiltinType("tuple")},
      {"type", BuiltinType("type")},
      {"zip", BuiltinType("zip")},
  };
}

// a function that warns each time it is called, then calls `f` (xacro's deprecate())
Value Deprecated(const Value& f, const std::string& message, const WarnFunction& warn) {
  return Value::Callable(f.fn->name, [f, message, warn](ValueList& a, Kwargs& kw) {
    warn(message);
    return CallValue(f, a, kw);
  });
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
    case Value::Type::kSet:
    case Value::Type::kFrozenSet: return static_cast<Int>(SetOf(v).size());
    case Value::Type::kRange: {
      const Int n = RangeLength(v);
      if (n > Int(INT64_MAX)) throw EvalError("Python int too large to convert to C ssize_t");
      return n;
    }
    default: throw EvalError("object of type '" + TypeName(v) + "' has no len()");
  }
}

std::unordered_map<std::string, Value> MakeGlobalSymbols(const Members& xacro_members,
                                                         const std::vector<std::string>& xacro_direct,
                                                         const WarnFunction& warn) {
  std::unordered_map<std::string, Value> g;
  const Members direct = DirectBuiltins();
  const Members math = MathMembers();
  const Members deprecated = {{"sorted", Value::Callable("sorted", Sorted)}, {"range", BuiltinType("range")}};
  Members python = direct;
  for (auto& m : PythonOnlyBuiltins()) python.push_back(m);
  python.insert(python.end(), deprecated.begin(), deprecated.end());
  for (const auto& [name, v] : direct) g[name] = v;
  for (const auto& [name, v] : math) g[name] = v;
  for (const auto& [name, v] : deprecated) {
    g[name] = Deprecated(v, "Using " + name + "() directly is deprecated. Use python." + name + "() instead.", warn);
  }
  for (const auto& [name, v] : xacro_members) {
    if (std::find(xacro_direct.begin(), xacro_direct.end(), name) != xacro_direct.end()) {
      g[name] = Deprecated(v, "Using " + name + "() directly is deprecated. Use xacro." + name + "() instead.", warn);
    }
  }
  g["python"] = Value::Module("python", Keyed(python));
  g["math"] = Value::Module("math", Keyed(math));
  g["xacro"] = Value::Module("xacro", Keyed(xacro_members));
  return g;
}

}  // namespace urdfsnap::xacro
