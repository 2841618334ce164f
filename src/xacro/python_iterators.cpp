// map, filter, zip, enumerate, reversed and range as CPython 3.11 has them.
#include "xacro/internal/python_iterators.h"

#include "xacro/internal/evaluation_budget.h"

namespace urdfsnap::xacro {
namespace {

using UInt = unsigned __int128;

const Int& Start(const Value& r) { return (*r.list)[0].i; }
const Int& Stop(const Value& r) { return (*r.list)[1].i; }
const Int& Step(const Value& r) { return (*r.list)[2].i; }

Int RangeArg(const Value& v) {
  if (!v.IsIntLike()) throw EvalError("'" + TypeName(v) + "' object cannot be interpreted as an integer");
  return AsInt(v);
}

// items start, start + step, ... (count of them), without a list
NextFunction Arithmetic(Int start, Int step, Int count) {
  return [start, step, count, k = Int(0)]() mutable -> std::optional<Value> {
    if (k == count) return std::nullopt;
    return Value::Integer(start + step * k++);
  };
}

}  // namespace

Iterator::Iterator(std::string type_name, NextFunction next)
    : type_name_(std::move(type_name)), next_(std::move(next)) {}

std::optional<Value> Iterator::Next() {
  if (ended_) return std::nullopt;
  std::optional<Value> item = next_();
  if (!item) {
    ended_ = true;
    next_ = nullptr;  // lets go of what it was reading
  }
  return item;
}

Iterator& IteratorOf(const Value& v) { return static_cast<Iterator&>(*v.object); }

Value MakeIterator(std::string type_name, NextFunction next) {
  Value r;
  r.type = Value::Type::kIterator;
  r.object = std::make_shared<Iterator>(std::move(type_name), std::move(next));
  return r;
}

Value MapIterator(const Value& f, const ValueList& iterables) {
  std::vector<NextFunction> sources;
  for (const Value& it : iterables) sources.push_back(IterateLazily(it));
  return MakeIterator("map", [f, sources]() -> std::optional<Value> {
    ValueList args;
    for (const NextFunction& source : sources) {
      std::optional<Value> item = source();
      if (!item) return std::nullopt;
      args.push_back(std::move(*item));
    }
    return CallValue(f, std::move(args));
  });
}

Value FilterIterator(const Value& f, const Value& iterable) {
  NextFunction source = IterateLazily(iterable);
  return MakeIterator("filter", [f, source]() -> std::optional<Value> {
    while (std::optional<Value> item = source()) {
      const bool keep = f.type == Value::Type::kNone ? Truthy(*item) : Truthy(CallValue(f, {*item}));
      if (keep) return item;
    }
    return std::nullopt;
  });
}

Value ZipIterator(const ValueList& iterables, bool strict) {
  std::vector<NextFunction> sources;
  for (const Value& it : iterables) sources.push_back(IterateLazily(it));
  return MakeIterator("zip", [sources, strict]() -> std::optional<Value> {
    if (sources.empty()) return std::nullopt;
    ValueList row;
    for (size_t k = 0; k < sources.size(); ++k) {
      std::optional<Value> item = sources[k]();
      if (item) {
        row.push_back(std::move(*item));
        continue;
      }
      if (!strict) return std::nullopt;
      // strict: all must end together
      const std::string plural = k == 1 ? " " : "s 1-";
      if (k > 0) {
        throw EvalError("zip() argument " + std::to_string(k + 1) + " is shorter than argument" + plural +
                        std::to_string(k));
      }
      for (size_t j = 1; j < sources.size(); ++j) {
        if (sources[j]()) {
          throw EvalError("zip() argument " + std::to_string(j + 1) + " is longer than argument" +
                          (j == 1 ? " " : "s 1-") + std::to_string(j));
        }
      }
      return std::nullopt;
    }
    return Value::Tuple(std::move(row));
  });
}

Value EnumerateIterator(const Value& iterable, Int start) {
  NextFunction source = IterateLazily(iterable);
  return MakeIterator("enumerate", [source, k = start]() mutable -> std::optional<Value> {
    std::optional<Value> item = source();
    if (!item) return std::nullopt;
    return Value::Tuple({Value::Integer(k++), std::move(*item)});
  });
}

Value ReversedIterator(const Value& sequence) {
  switch (sequence.type) {
    case Value::Type::kRange: {
      const Int n = RangeLength(sequence);
      CheckListSize(n, "range()");
      return MakeIterator("range_iterator", Arithmetic(Start(sequence) + (n - 1) * Step(sequence), -Step(sequence), n));
    }
    case Value::Type::kList:
    case Value::Type::kTuple:
    case Value::Type::kStr:
    case Value::Type::kDict: {
      ValueList items = Iterate(sequence);
      const size_t n = items.size();
      const char* name = sequence.type == Value::Type::kList ? "list_reverseiterator"
                         : sequence.type == Value::Type::kDict ? "dict_reversekeyiterator"
                                                               : "reversed";
      return MakeIterator(name, [items = std::move(items), k = n]() mutable -> std::optional<Value> {
        if (k == 0) return std::nullopt;
        return items[--k];
      });
    }
    default: throw EvalError("'" + TypeName(sequence) + "' object is not reversible");
  }
}

Value MakeRange(const ValueList& args) {
  if (args.empty()) throw EvalError("range expected at least 1 argument, got 0");
  if (args.size() > 3) throw EvalError("range expected at most 3 arguments, got " + std::to_string(args.size()));
  Int start = 0, stop = 0, step = 1;
  if (args.size() == 1) {
    stop = RangeArg(args[0]);
  } else {
    start = RangeArg(args[0]);
    stop = RangeArg(args[1]);
    if (args.size() == 3) step = RangeArg(args[2]);
  }
  if (step == 0) throw EvalError("range() arg 3 must not be zero");
  const Value r = Value::Range(start, stop, step);
  // the length must fit in an Int (Python's has no bound; a longer range is of no use here)
  const UInt span = step > 0 ? UInt(stop) - UInt(start) : UInt(start) - UInt(stop);
  const bool empty = step > 0 ? stop <= start : stop >= start;
  const UInt stride = step > 0 ? UInt(step) : -UInt(step);
  if (!empty && (span - 1) / stride + 1 > UInt(~UInt(0) >> 1)) {
    throw EvalError("range() too large: its length does not fit in 127 bits");
  }
  return r;
}

Int RangeLength(const Value& r) {
  const Int start = Start(r), stop = Stop(r), step = Step(r);
  if (step > 0 ? stop <= start : stop >= start) return 0;
  const UInt span = step > 0 ? UInt(stop) - UInt(start) : UInt(start) - UInt(stop);
  const UInt stride = step > 0 ? UInt(step) : -UInt(step);
  return static_cast<Int>((span - 1) / stride + 1);
}

Value RangeItem(const Value& r, Int index) {
  const Int n = RangeLength(r);
  if (index < 0) index += n;
  if (index < 0 || index >= n) throw EvalError("range object index out of range");
  return Value::Integer(Start(r) + index * Step(r));
}

bool RangeContains(const Value& r, const Value& x) {
  if (x.IsIntLike()) {
    const Int v = AsInt(x), start = Start(r), stop = Stop(r), step = Step(r);
    const bool inside = step > 0 ? (start <= v && v < stop) : (stop < v && v <= start);
    return inside && (v - start) % step == 0;
  }
  const NextFunction next = IterateRange(r);
  while (std::optional<Value> item = next()) {
    if (Equal(*item, x)) return true;
  }
  return false;
}

bool RangeEqual(const Value& a, const Value& b) {
  const Int n = RangeLength(a);
  if (n != RangeLength(b)) return false;
  if (n == 0) return true;
  if (Start(a) != Start(b)) return false;
  return n == 1 || Step(a) == Step(b);
}

std::string RangeRepr(const Value& r) {
  std::string out = "range(" + ToStr((*r.list)[0]) + ", " + ToStr((*r.list)[1]);
  if (Step(r) != 1) out += ", " + ToStr((*r.list)[2]);
  return out + ")";
}

NextFunction IterateRange(const Value& r) {
  const Int n = RangeLength(r);
  CheckListSize(n, "range()");
  return Arithmetic(Start(r), Step(r), n);
}

}  // namespace urdfsnap::xacro
