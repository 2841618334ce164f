// The builtin types of xacro's expressions and what calling each does: int('3'), complex(1, 2),
// set([1, 2]), range(3), zip(a, b), type(x), ... with CPython's arguments and errors.
#include <algorithm>
#include <cmath>

#include "xacro/internal/call_arguments.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/operators.h"
#include "xacro/internal/python_complex.h"
#include "xacro/internal/python_hash.h"
#include "xacro/internal/python_iterators.h"
#include "xacro/internal/python_set.h"
#include "xacro/internal/python_types.h"

namespace urdfsnap::xacro {
namespace {

Value ToInt(ValueList& a, Kwargs& kw) {
  TakesAtMost("int", a, 2);
  OnlyKeywords("int", kw, {"base"});
  if (a.empty()) return Value::Integer(0);
  const Value& v = a[0];
  int base = 10;
  if (a.size() > 1) base = static_cast<int>(AsIndex(a[1], "base"));
  if (const Value* b = Keyword(kw, "base")) base = static_cast<int>(AsIndex(*b, "base"));
  if (v.type == Value::Type::kStr) {
    if (base == 10) {
      if (auto i = ParseIntText(v.s.str())) return Value::Integer(*i);
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

Value ToFloat(ValueList& a, Kwargs& kw) {
  Expected("float", a, 0, 1);
  NoKeywords("float", kw);
  if (a.empty()) return Value::Float(0.0);
  const Value& v = a[0];
  if (v.IsNumber()) return Value::Float(AsDouble(v));
  if (v.type == Value::Type::kStr) {
    if (auto f = ParseFloatText(v.s.str())) return Value::Float(*f);
    throw EvalError("could not convert string to float: " + Repr(v));
  }
  throw EvalError("float() argument must be a string or a real number, not '" + TypeName(v) + "'");
}

Value ToComplex(ValueList& a, Kwargs& kw) {
  TakesAtMost("complex", a, 2);
  OnlyKeywords("complex", kw, {"real", "imag"});
  const Value* real = a.size() > 0 ? &a[0] : Keyword(kw, "real");
  const Value* imag = a.size() > 1 ? &a[1] : Keyword(kw, "imag");
  if (real && real->type == Value::Type::kStr) {
    if (imag) throw EvalError("complex() can't take second arg if first is a string");
    const auto [re, im] = ParseComplexText(real->s.str());
    return Value::Complex(re, im);
  }
  if (imag && imag->type == Value::Type::kStr) throw EvalError("complex() second arg can't be a string");
  if (real && real->type == Value::Type::kComplex && !imag) return *real;
  const auto number = [](const Value* v, const char* which) {
    if (v && !v->IsNumber() && v->type != Value::Type::kComplex) {
      throw EvalError(std::string("complex() ") + which + " must be " +
                      (std::string(which) == "first argument" ? "a string or a number" : "a number") + ", not '" +
                      TypeName(*v) + "'");
    }
  };
  number(real, "first argument");
  number(imag, "second argument");
  // complex(a, b) is a + b*1j for complex a and b too (CPython's complex_new_impl)
  double re = 0.0, im = 0.0;
  if (real) re = real->type == Value::Type::kComplex ? real->f : AsDouble(*real);
  if (imag) {
    im = imag->type == Value::Type::kComplex ? imag->f : AsDouble(*imag);
    if (imag->type == Value::Type::kComplex) re -= imag->imag;
    if (real && real->type == Value::Type::kComplex) im += real->imag;
  }
  return Value::Complex(re, im);
}

Value ToStrValue(ValueList& a, Kwargs& kw) {
  TakesAtMost("str", a, 3);
  OnlyKeywords("str", kw, {"object", "encoding", "errors"});
  const Value* object = a.empty() ? Keyword(kw, "object") : &a[0];
  if (a.size() > 1 || Keyword(kw, "encoding") || Keyword(kw, "errors")) {
    if (a.size() > 1 && a[1].type != Value::Type::kStr) {
      throw EvalError("str() argument 'encoding' must be str, not " + TypeName(a[1]));
    }
    if (object && object->type == Value::Type::kStr) throw EvalError("decoding str is not supported");
    throw EvalError("decoding to str: need a bytes-like object, " + TypeName(object ? *object : Value::Str("")) + " found");
  }
  if (!object) return Value::Str("");
  if (object->type == Value::Type::kStr) return *object;  // str(s) is s
  std::string text = ToStr(*object);
  EvaluationBudget::ChargeBytes(text.size());
  return Value::Str(std::move(text));
}

Value ToBool(ValueList& a, Kwargs& kw) {
  Expected("bool", a, 0, 1);
  NoKeywords("bool", kw);
  return Value::Bool(!a.empty() && Truthy(a[0]));
}

Value ToList(ValueList& a, Kwargs& kw) {
  Expected("list", a, 0, 1);
  NoKeywords("list", kw);
  return Value::List(a.empty() ? ValueList{} : Iterate(a[0]));
}

Value ToTuple(ValueList& a, Kwargs& kw) {
  Expected("tuple", a, 0, 1);
  NoKeywords("tuple", kw);
  if (!a.empty() && a[0].type == Value::Type::kTuple) return a[0];
  return Value::Tuple(a.empty() ? ValueList{} : Iterate(a[0]));
}

Value ToDict(ValueList& a, Kwargs& kw) {
  Expected("dict", a, 0, 1);
  DictBuilder items;
  auto put = [&items](const Value& key, const Value& value) { items.Put(key, value); };
  if (!a.empty()) {
    if (a[0].type == Value::Type::kDict) {
      for (const auto& kv : a[0].dict->items) put(kv.first, kv.second);
    } else {
      const NextFunction next = IterateLazily(a[0]);
      for (size_t k = 0; std::optional<Value> pair = next(); ++k) {
        // a pair is usually a tuple or list: read it in place
        if (!pair->IsSequence() && !IsIterable(*pair)) {
          throw EvalError("cannot convert dictionary update sequence element #" + std::to_string(k) + " to a sequence");
        }
        const ValueList kv = pair->IsSequence() ? *pair->list : Iterate(*pair);
        if (kv.size() != 2) {
          throw EvalError("dictionary update sequence element #" + std::to_string(k) + " has length " +
                          std::to_string(kv.size()) + "; 2 is required");
        }
        put(kv[0], kv[1]);
      }
    }
  }
  for (auto& [k, v] : kw) put(Value::Str(k), v);
  return Value::Dict(items.Take());
}

Value ToYamlDict(ValueList& a, Kwargs& kw) { return Wrapped(ToDict(a, kw), true); }

Value ToYamlList(ValueList& a, Kwargs& kw) { return Wrapped(ToList(a, kw), true); }

template <Value::Type kType>
Value ToSet(ValueList& a, Kwargs& kw) {
  const char* name = kType == Value::Type::kSet ? "set" : "frozenset";
  Expected(name, a, 0, 1);
  NoKeywords(name, kw);
  return a.empty() ? MakeSet(kType) : SetFromIterable(kType, a[0]);
}

Value ToRange(ValueList& a, Kwargs& kw) {
  NoKeywords("range", kw);
  return MakeRange(a);
}

Value ToSlice(ValueList& a, Kwargs& kw) {
  NoKeywords("slice", kw);
  Expected("slice", a, 1, 3);
  if (a.size() == 1) return Value::SliceOf(Value::None(), a[0], Value::None());
  return Value::SliceOf(a[0], a[1], a.size() > 2 ? a[2] : Value::None());
}

Value ToMap(ValueList& a, Kwargs& kw) {
  NoKeywords("map", kw);
  if (a.size() < 2) throw EvalError("map() must have at least two arguments.");
  return MapIterator(a[0], ValueList(a.begin() + 1, a.end()));
}

Value ToFilter(ValueList& a, Kwargs& kw) {
  NoKeywords("filter", kw);
  Expected("filter", a, 2, 2);
  return FilterIterator(a[0], a[1]);
}

Value ToZip(ValueList& a, Kwargs& kw) {
  OnlyKeywords("zip", kw, {"strict"});
  const Value* strict = Keyword(kw, "strict");
  return ZipIterator(a, strict && Truthy(*strict));
}

Value ToEnumerate(ValueList& a, Kwargs& kw) {
  TakesAtMost("enumerate", a, 2);
  OnlyKeywords("enumerate", kw, {"iterable", "start"});
  const Value* iterable = a.empty() ? Keyword(kw, "iterable") : &a[0];
  if (!iterable) throw EvalError("enumerate() missing required argument 'iterable'");
  const Value* start = a.size() > 1 ? &a[1] : Keyword(kw, "start");
  if (start && !start->IsIntLike()) {
    throw EvalError("'" + TypeName(*start) + "' object cannot be interpreted as an integer");
  }
  return EnumerateIterator(*iterable, start ? AsInt(*start) : 0);
}

Value ToReversed(ValueList& a, Kwargs& kw) {
  NoKeywords("reversed", kw);
  Expected("reversed", a, 1, 1);
  return ReversedIterator(a[0]);
}

Value ToType(ValueList& a, Kwargs& kw) {
  NoKeywords("type", kw);
  if (a.size() == 1) return TypeOfValue(a[0]);
  if (a.size() != 3) throw EvalError("type() takes 1 or 3 arguments");
  return MakeClass(a[0], a[1], a[2]);
}

Value ToNone(ValueList& a, Kwargs& kw) {
  if (!a.empty() || !kw.empty()) throw EvalError("NoneType takes no arguments");
  return Value::None();
}

}  // namespace

const std::vector<TypeConstructor>& BuiltinTypeTable() {
  static const std::vector<TypeConstructor> table = {
      {"type", "", "", ToType},
      {"NoneType", "", "", ToNone},
      {"int", "", "", ToInt},
      {"bool", "", "int", ToBool},
      {"float", "", "", ToFloat},
      {"complex", "", "", ToComplex},
      {"str", "", "", ToStrValue},
      {"list", "", "", ToList},
      {"tuple", "", "", ToTuple},
      {"dict", "", "", ToDict},
      {"set", "", "", ToSet<Value::Type::kSet>},
      {"frozenset", "", "", ToSet<Value::Type::kFrozenSet>},
      {"range", "", "", ToRange},
      {"slice", "", "", ToSlice},
      {"map", "", "", ToMap},
      {"filter", "", "", ToFilter},
      {"zip", "", "", ToZip},
      {"enumerate", "", "", ToEnumerate},
      {"reversed", "", "", ToReversed},
      {"list_reverseiterator", "", "", nullptr},
      {"range_iterator", "", "", nullptr},
      {"dict_reversekeyiterator", "", "", nullptr},
      {"builtin_function_or_method", "", "", nullptr},
      {"UnionType", "types", "", nullptr},
      {"NameSpace", "xacro", "", nullptr},
      {"Element", "xml.dom.minidom", "", nullptr},
      {"YamlDictWrapper", "xacro", "dict", ToYamlDict},
      {"YamlListWrapper", "xacro", "list", ToYamlList},
  };
  return table;
}

}  // namespace urdfsnap::xacro
