// Python operator semantics on values.
#include "xacro/internal/operators.h"

#include <cmath>

#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/python_complex.h"
#include "xacro/internal/python_hash.h"
#include "xacro/internal/python_iterators.h"
#include "xacro/internal/python_set.h"
#include "xacro/internal/python_types.h"
#include "xacro/internal/string_format.h"

namespace urdfsnap::xacro {
namespace {

[[noreturn]] void Unsupported(const std::string& op, const Value& a, const Value& b) {
  throw EvalError("unsupported operand type(s) for " + op + ": '" + TypeName(a) + "' and '" + TypeName(b) + "'");
}

[[noreturn]] void Overflow() { throw EvalError("integer overflow: the result needs more than 127 bits"); }

Int CheckedPow(Int base, Int exp) {
  Int result = 1;
  while (exp > 0) {
    if (exp & 1) {
      if (__builtin_mul_overflow(result, base, &result)) Overflow();
    }
    exp >>= 1;
    if (exp > 0 && __builtin_mul_overflow(base, base, &base)) Overflow();
  }
  return result;
}

Int FloorDiv(Int a, Int b) {
  if (b == 0) throw EvalError("integer division or modulo by zero");
  Int q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

Int FloorMod(Int a, Int b) {
  if (b == 0) throw EvalError("integer division or modulo by zero");
  Int r = a % b;
  if (r != 0 && ((r < 0) != (b < 0))) r += b;
  return r;
}

double FloatMod(double a, double b) {
  if (b == 0.0) throw EvalError("float modulo");
  double r = std::fmod(a, b);
  if (r != 0.0) {
    if ((r < 0) != (b < 0)) r += b;
  } else {
    r = std::copysign(0.0, b);
  }
  return r;
}

Value IntArith(const std::string& op, Int x, Int y) {
  Int r = 0;
  if (op == "+") {
    if (__builtin_add_overflow(x, y, &r)) Overflow();
  } else if (op == "-") {
    if (__builtin_sub_overflow(x, y, &r)) Overflow();
  } else if (op == "*") {
    if (__builtin_mul_overflow(x, y, &r)) Overflow();
  } else if (op == "/") {
    if (y == 0) throw EvalError("division by zero");
    return Value::Float(static_cast<double>(x) / static_cast<double>(y));
  } else if (op == "//") {
    r = FloorDiv(x, y);
  } else if (op == "%") {
    r = FloorMod(x, y);
  } else if (op == "**") {
    // a negative exponent makes it float ** float
    if (y < 0) return FloatPower(static_cast<double>(x), static_cast<double>(y));
    r = CheckedPow(x, y);
  } else if (op == "<<" || op == ">>") {
    if (y < 0) throw EvalError("negative shift count");
    if (op == ">>") {
      r = y >= 127 ? (x < 0 ? -1 : 0) : (x >> static_cast<int>(y));
    } else {
      if (y >= 127 || (x != 0 && (x > (Int(1) << (126 - static_cast<int>(y))) ||
                                  x < -(Int(1) << (126 - static_cast<int>(y)))))) {
        Overflow();
      }
      r = x * (Int(1) << static_cast<int>(y));
    }
  } else if (op == "&") {
    r = x & y;
  } else if (op == "|") {
    r = x | y;
  } else if (op == "^") {
    r = x ^ y;
  }
  return Value::Integer(r);
}

Value FloatArith(const std::string& op, const Value& a, const Value& b) {
  const double x = AsDouble(a), y = AsDouble(b);
  if (op == "+") return Value::Float(x + y);
  if (op == "-") return Value::Float(x - y);
  if (op == "*") return Value::Float(x * y);
  if (op == "/") {
    if (y == 0.0) throw EvalError("float division by zero");
    return Value::Float(x / y);
  }
  if (op == "//") {
    if (y == 0.0) throw EvalError("float floor division by zero");
    const double mod = FloatMod(x, y);
    double div = (x - mod) / y;
    if (div != 0.0) {
      double floordiv = std::floor(div);
      if (div - floordiv > 0.5) floordiv += 1.0;
      div = floordiv;
    } else {
      div = std::copysign(0.0, x / y);
    }
    return Value::Float(div);
  }
  if (op == "%") {
    if (y == 0.0) throw EvalError("float modulo");
    return Value::Float(FloatMod(x, y));
  }
  if (op == "**") return FloatPower(x, y);
  Unsupported(op, a, b);
}

// s OP t for two sets: | & - ^ (the result has s's type)
Value SetOperator(const std::string& op, const Value& s, const Value& t) {
  if (op == "|") return SetUnion(s, {t});
  if (op == "&") return SetIntersection(s, t);
  if (op == "-") return SetDifference(s, t);
  if (op == "^") return SetSymmetricDifference(s, t);
  Unsupported(op, s, t);
}

Value Repeat(const Value& seq, const Value& count) {
  const size_t unit = seq.type == Value::Type::kStr ? seq.s.size() : seq.list->size();
  // an empty sequence stays empty however often it is repeated (found by fuzzing: '[] * 10**12'
  // looped 10^12 times)
  const Int n = unit == 0 ? 0 : std::max<Int>(0, AsInt(count));
  const size_t limit = seq.type == Value::Type::kStr ? kMaxStringBytes : kMaxListItems;
  if (unit != 0 && n > static_cast<Int>(limit / unit)) {
    throw EvalError("result of repetition is too large (limit " + std::to_string(limit) + ")");
  }
  if (seq.type == Value::Type::kStr) {
    CheckStringSize(unit * static_cast<size_t>(n), "repeated string");
    std::string out;
    out.reserve(unit * static_cast<size_t>(n));
    for (Int k = 0; k < n; ++k) out += seq.s.str();
    return Value::Str(std::move(out));
  }
  CheckListSize(n * static_cast<Int>(unit), "repeated sequence");
  ValueList out;
  for (Int k = 0; k < n; ++k) out.insert(out.end(), seq.list->begin(), seq.list->end());
  Value r = seq.type == Value::Type::kList ? Value::List(std::move(out)) : Value::Tuple(std::move(out));
  return r;
}

long NormalizeIndex(long index, size_t size) {
  if (index < 0) index += static_cast<long>(size);
  return index;
}

}  // namespace

Int FloatToInt(double v) {
  if (std::isnan(v)) throw EvalError("cannot convert float NaN to integer");
  if (std::isinf(v)) throw EvalError("cannot convert float infinity to integer");
  if (std::fabs(v) >= 1.7e38) Overflow();
  return static_cast<Int>(v);
}

long AsIndex(const Value& v, const char* what) {
  if (!v.IsIntLike()) {
    throw EvalError(std::string(what) + " must be integers or slices, not " + TypeName(v));
  }
  const Int i = AsInt(v);
  if (i > (Int(1) << 62) || i < -(Int(1) << 62)) throw EvalError("index out of range");
  return static_cast<long>(i);
}

Value BinaryOp(const std::string& op, const Value& a, const Value& b) {
  if (a.IsNumber() && b.IsNumber()) {
    if (a.IsIntLike() && b.IsIntLike()) return IntArith(op, AsInt(a), AsInt(b));
    if (op == "<<" || op == ">>" || op == "&" || op == "|" || op == "^") Unsupported(op, a, b);
    return FloatArith(op, a, b);
  }
  const auto numeric = [](const Value& v) { return v.IsNumber() || v.type == Value::Type::kComplex; };
  if (numeric(a) && numeric(b)) return ComplexArith(op, a, b);
  if (a.IsAnySet() && b.IsAnySet()) return SetOperator(op, a, b);
  const auto typelike = [](const Value& v) { return v.type == Value::Type::kType || v.type == Value::Type::kUnion; };
  if (op == "|" && (typelike(a) || typelike(b))) return TypeUnion(a, b);
  if (op == "+") {
    if (a.type == Value::Type::kStr && b.type == Value::Type::kStr) {
      CheckStringSize(a.s.size() + b.s.size(), "concatenated string");
      return Value::Str(a.s.str() + b.s.str());
    }
    if (a.IsSequence() && a.type == b.type) {
      CheckListSize(static_cast<Int>(a.list->size() + b.list->size()), "concatenated sequence");
      ValueList out = *a.list;
      out.insert(out.end(), b.list->begin(), b.list->end());
      return a.type == Value::Type::kList ? Value::List(std::move(out)) : Value::Tuple(std::move(out));
    }
    if (a.type == Value::Type::kStr || b.type == Value::Type::kStr) {
      const Value& other = a.type == Value::Type::kStr ? b : a;
      if (a.type == Value::Type::kStr) {
        throw EvalError("can only concatenate str (not \"" + TypeName(other) + "\") to str");
      }
    }
  }
  if (op == "*") {
    const bool a_seq = a.type == Value::Type::kStr || a.IsSequence();
    const bool b_seq = b.type == Value::Type::kStr || b.IsSequence();
    if (a_seq && b.IsIntLike()) return Repeat(a, b);
    if (b_seq && a.IsIntLike()) return Repeat(b, a);
    if (a_seq || b_seq) {
      throw EvalError("can't multiply sequence by non-int of type '" + TypeName(a_seq ? b : a) + "'");
    }
  }
  if (op == "%" && a.type == Value::Type::kStr) return Value::Str(PercentFormat(a.s, b));
  Unsupported(op, a, b);
}

Value UnaryOp(const std::string& op, const Value& a) {
  if (a.type == Value::Type::kComplex && op != "~") return Value::Complex(op == "-" ? -a.f : a.f, op == "-" ? -a.imag : a.imag);
  if (!a.IsNumber()) throw EvalError("bad operand type for unary " + op + ": '" + TypeName(a) + "'");
  if (op == "~") {
    if (!a.IsIntLike()) throw EvalError("bad operand type for unary ~: 'float'");
    return Value::Integer(~AsInt(a));
  }
  if (a.type == Value::Type::kFloat) return Value::Float(op == "-" ? -a.f : a.f);
  const Int v = AsInt(a);
  if (op == "-") {
    Int r;
    if (__builtin_sub_overflow(Int(0), v, &r)) Overflow();
    return Value::Integer(r);
  }
  return Value::Integer(v);
}

bool Contains(const Value& container, const Value& item) {
  switch (container.type) {
    case Value::Type::kStr:
      if (item.type != Value::Type::kStr) {
        throw EvalError("'in <string>' requires string as left operand, not " + TypeName(item));
      }
      return container.s.find(item.s.str()) != std::string::npos;
    case Value::Type::kList:
    case Value::Type::kTuple:
      for (const Value& v : *container.list) {
        if (Equal(v, item)) return true;
      }
      return false;
    case Value::Type::kDict: return container.dict->Find(item) != DictItems::kNone;
    case Value::Type::kModule:
      for (const auto& kv : container.dict->items) {
        if (Equal(kv.first, item)) return true;
      }
      return false;
    case Value::Type::kSet:
    case Value::Type::kFrozenSet: return SetOf(container).Contains(item);
    case Value::Type::kRange: return RangeContains(container, item);
    case Value::Type::kIterator: {
      // reads the iterator up to the item, as Python does
      const NextFunction next = IterateLazily(container);
      while (std::optional<Value> v = next()) {
        if (Equal(*v, item)) return true;
      }
      return false;
    }
    default: throw EvalError("argument of type '" + TypeName(container) + "' is not iterable");
  }
}

namespace {

// a slice object's bound: None or an int (huge ints clamp, as they would to any length)
std::optional<long> SliceBound(const Value& b) {
  if (b.type == Value::Type::kNone) return std::nullopt;
  if (!b.IsIntLike()) throw EvalError("slice indices must be integers or None or have an __index__ method");
  return static_cast<long>(std::clamp(AsInt(b), -(Int(1) << 62), Int(1) << 62));
}

// the first index, clamped stop, step and count of the items a slice takes from `size` items (CPython's
// PySlice_AdjustIndices)
struct SliceIndices {
  Int first, stop, step, count;  // stop: the clamped stop bound
};

SliceIndices AdjustSlice(std::optional<long> start, std::optional<long> stop, std::optional<long> step, Int size) {
  const Int st = step.value_or(1);
  if (st == 0) throw EvalError("slice step cannot be zero");
  auto clamp = [&](std::optional<long> bound, Int dflt) {
    if (!bound) return dflt;
    const Int b = *bound < 0 ? *bound + size : *bound;
    if (st > 0) return std::clamp(b, Int(0), size);
    return std::clamp(b, Int(-1), size - 1);
  };
  const Int from = clamp(start, st > 0 ? 0 : size - 1);
  const Int to = clamp(stop, st > 0 ? size : -1);
  Int count = 0;
  if (st > 0 && to > from) count = (to - from - 1) / st + 1;
  if (st < 0 && to < from) count = (from - to - 1) / -st + 1;
  return {from, to, st, count};
}

}  // namespace

Value SliceIndicesTuple(const Value& slice, Int length) {
  if (length < 0) throw EvalError("length should not be negative");
  const ValueList& p = *slice.list;
  const SliceIndices s = AdjustSlice(SliceBound(p[0]), SliceBound(p[1]), SliceBound(p[2]), length);
  return Value::Tuple({Value::Integer(s.first), Value::Integer(s.stop), Value::Integer(s.step)});
}

Value Subscript(const Value& v, const Value& index) {
  if (index.type == Value::Type::kSlice && v.type != Value::Type::kDict) {
    const ValueList& p = *index.list;
    return Slice(v, SliceBound(p[0]), SliceBound(p[1]), SliceBound(p[2]));
  }
  switch (v.type) {
    case Value::Type::kList:
    case Value::Type::kTuple:
    case Value::Type::kStr: {
      const char* kind = v.type == Value::Type::kStr ? "string" : (v.type == Value::Type::kList ? "list" : "tuple");
      const long i = AsIndex(index, (std::string(kind) + " indices").c_str());
      const size_t size = v.type == Value::Type::kStr ? v.s.size() : v.list->size();
      const long k = NormalizeIndex(i, size);
      if (k < 0 || k >= static_cast<long>(size)) throw EvalError(std::string(kind) + " index out of range");
      if (v.type == Value::Type::kStr) return Value::Str(v.s.substr(static_cast<size_t>(k), 1));
      return Wrapped((*v.list)[static_cast<size_t>(k)], v.wrapped);
    }
    case Value::Type::kRange:
      if (!index.IsIntLike()) throw EvalError("range indices must be integers or slices, not " + TypeName(index));
      return RangeItem(v, AsInt(index));
    case Value::Type::kDict: {
      const size_t k = v.dict->Find(index);
      if (k != DictItems::kNone) return Wrapped(v.dict->items[k].second, v.wrapped);
      if (v.wrapped) throw EvalError("The yaml dictionary has no key '" + ToStr(index) + "'");
      throw EvalError(Repr(index));
    }
    default: throw EvalError("'" + TypeName(v) + "' object is not subscriptable");
  }
}

Value Slice(const Value& v, std::optional<long> start, std::optional<long> stop, std::optional<long> step) {
  if (v.type == Value::Type::kRange) {
    const SliceIndices s = AdjustSlice(start, stop, step, RangeLength(v));
    const Int r_start = AsInt((*v.list)[0]), r_step = AsInt((*v.list)[2]);
    return Value::Range(r_start + s.first * r_step, r_start + s.stop * r_step, r_step * s.step);
  }
  if (v.type != Value::Type::kStr && !v.IsSequence()) {
    throw EvalError("'" + TypeName(v) + "' object is not subscriptable");
  }
  const Int size = static_cast<Int>(v.type == Value::Type::kStr ? v.s.size() : v.list->size());
  const SliceIndices s = AdjustSlice(start, stop, step, size);
  std::string text;
  ValueList items;
  for (Int n = 0, k = s.first; n < s.count; ++n, k += s.step) {
    if (v.type == Value::Type::kStr) {
      text += v.s[static_cast<size_t>(k)];
    } else {
      items.push_back((*v.list)[static_cast<size_t>(k)]);
    }
  }
  if (v.type == Value::Type::kStr) {
    EvaluationBudget::ChargeBytes(text.size());
    return Value::Str(std::move(text));
  }
  Value r = v.type == Value::Type::kList ? Value::List(std::move(items)) : Value::Tuple(std::move(items));
  return Wrapped(r, v.wrapped);
}

}  // namespace urdfsnap::xacro
