// Python's rules for values: constructors, str()/repr(), truth, equality, ordering, calls and
// iteration.
#include "xacro/internal/python_value.h"

#include <cmath>
#include <cstdio>

#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/python_complex.h"
#include "xacro/internal/python_hash.h"
#include "xacro/internal/python_iterators.h"
#include "xacro/internal/python_set.h"
#include "xacro/internal/python_types.h"
#include "xacro/internal/symbol_table.h"

namespace urdfsnap::xacro {

SharedString::SharedString(std::string text)
    : text_(text.empty() ? nullptr : std::make_shared<const std::string>(std::move(text))) {}

const std::string& SharedString::Empty() {
  static const std::string empty;
  return empty;
}

Value Value::Bool(bool v) {
  Value r;
  r.type = Type::kBool;
  r.b = v;
  return r;
}

Value Value::Integer(Int v) {
  Value r;
  r.type = Type::kInt;
  r.i = v;
  return r;
}

Value Value::Float(double v) {
  Value r;
  r.type = Type::kFloat;
  r.f = v;
  return r;
}

Value Value::Complex(double real, double imag) {
  Value r;
  r.type = Type::kComplex;
  r.f = real;
  r.imag = imag;
  return r;
}

Value Value::Str(std::string v) {
  Value r;
  r.type = Type::kStr;
  r.s = std::move(v);
  return r;
}

Value Value::List(ValueList items) {
  EvaluationBudget::ChargeContainer(items.size());  // every list and tuple, however it was made
  Value r;
  r.type = Type::kList;
  r.list = std::make_shared<ValueList>(std::move(items));
  return r;
}

Value Value::Tuple(ValueList items) {
  Value r = List(std::move(items));
  r.type = Type::kTuple;
  return r;
}

Value Value::Dict(std::vector<std::pair<Value, Value>> items) {
  EvaluationBudget::ChargeContainer(items.size());
  Value r;
  r.type = Type::kDict;
  r.dict = std::make_shared<DictItems>();
  r.dict->items = std::move(items);
  return r;
}

Value Value::Range(Int start, Int stop, Int step) {
  Value r = List({Integer(start), Integer(stop), Integer(step)});
  r.type = Type::kRange;
  return r;
}

Value Value::SliceOf(Value start, Value stop, Value step) {
  Value r = List({std::move(start), std::move(stop), std::move(step)});
  r.type = Type::kSlice;
  return r;
}

Value Value::Module(std::string name, std::vector<std::pair<Value, Value>> members) {
  Value r = Dict(std::move(members));
  r.type = Type::kModule;
  r.s = std::move(name);
  return r;
}

Value Value::Callable(std::string name, std::function<Value(ValueList&, Kwargs&)> call) {
  Value r;
  r.type = Type::kFunction;
  r.fn = std::make_shared<Function>(Function{std::move(name), std::move(call), ""});
  return r;
}

Value Value::Scope(std::shared_ptr<Table> table) {
  Value r;
  r.type = Type::kScope;
  r.scope = std::move(table);
  return r;
}

Value Value::Block(const Node* node) {
  Value r;
  r.type = Type::kBlock;
  r.block = node;
  return r;
}

std::string TypeName(const Value& v) {
  switch (v.type) {
    case Value::Type::kNone: return "NoneType";
    case Value::Type::kBool: return "bool";
    case Value::Type::kInt: return "int";
    case Value::Type::kFloat: return "float";
    case Value::Type::kStr: return "str";
    case Value::Type::kTuple: return "tuple";
    default: return TypeOf(TypeOfValue(v)).name;
  }
}

static std::string ReprStr(const std::string& s) {
  const bool has_single = s.find('\'') != std::string::npos;
  const char quote = (has_single && s.find('"') == std::string::npos) ? '"' : '\'';
  std::string out(1, quote);
  for (unsigned char c : s) {
    if (c == '\\') {
      out += "\\\\";
    } else if (c == static_cast<unsigned char>(quote)) {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + quote;
}

std::string Repr(const Value& v) {
  switch (v.type) {
    case Value::Type::kStr: return ReprStr(v.s);
    case Value::Type::kList:
    case Value::Type::kTuple: {
      // containers are checked piece by piece, so that no repr grows past the string limit
      const bool tuple = v.type == Value::Type::kTuple;
      std::string out = tuple ? "(" : "[";
      for (size_t k = 0; k < v.list->size(); ++k) {
        if (k) out += ", ";
        AppendBounded(out, Repr((*v.list)[k]), "repr");
      }
      if (tuple && v.list->size() == 1) out += ",";
      return out + (tuple ? ")" : "]");
    }
    case Value::Type::kDict: {
      std::string out = "{";
      bool first = true;
      for (const auto& [key, value] : v.dict->items) {
        if (!first) out += ", ";
        first = false;
        AppendBounded(out, Repr(key), "repr");
        out += ": ";
        AppendBounded(out, Repr(value), "repr");
      }
      return out + "}";
    }
    case Value::Type::kComplex: return FormatComplex(v.f, v.imag);
    case Value::Type::kSet:
    case Value::Type::kFrozenSet: return SetRepr(v);
    case Value::Type::kRange: return RangeRepr(v);
    case Value::Type::kSlice: {
      const ValueList& p = *v.list;
      return "slice(" + Repr(p[0]) + ", " + Repr(p[1]) + ", " + Repr(p[2]) + ")";
    }
    case Value::Type::kIterator: {
      char address[32];
      std::snprintf(address, sizeof address, "%p", static_cast<const void*>(v.object.get()));
      return "<" + IteratorOf(v).type_name() + " object at " + address + ">";
    }
    case Value::Type::kType:
    case Value::Type::kUnion: return TypeRepr(v);
    case Value::Type::kInstance: return InstanceRepr(v);
    case Value::Type::kFunction:
      return v.fn->repr.empty() ? "<built-in function " + v.fn->name + ">" : v.fn->repr;
    case Value::Type::kModule: return "<module '" + v.s + "'>";
    default: return ToStr(v);
  }
}

std::string ToStr(const Value& v) {
  switch (v.type) {
    case Value::Type::kNone: return "None";
    case Value::Type::kBool: return v.b ? "True" : "False";
    case Value::Type::kInt: return FormatInt(v.i);
    case Value::Type::kFloat: return FormatFloat(v.f);
    case Value::Type::kStr: return v.s;
    case Value::Type::kScope: return "<xacro.NameSpace object>";
    case Value::Type::kBlock: return "<DOM Element>";
    default: return Repr(v);
  }
}

bool Truthy(const Value& v) {
  switch (v.type) {
    case Value::Type::kNone: return false;
    case Value::Type::kBool: return v.b;
    case Value::Type::kInt: return v.i != 0;
    case Value::Type::kFloat: return v.f != 0.0;
    case Value::Type::kComplex: return v.f != 0.0 || v.imag != 0.0;
    case Value::Type::kStr: return !v.s.empty();
    case Value::Type::kList:
    case Value::Type::kTuple: return !v.list->empty();
    case Value::Type::kDict: return !v.dict->items.empty();
    case Value::Type::kSet:
    case Value::Type::kFrozenSet: return SetOf(v).size() != 0;
    case Value::Type::kRange: return RangeLength(v) != 0;
    default: return true;
  }
}

Int AsInt(const Value& v) { return v.type == Value::Type::kBool ? Int(v.b) : v.i; }

double AsDouble(const Value& v) {
  if (v.type == Value::Type::kFloat) return v.f;
  return static_cast<double>(AsInt(v));
}

bool Equal(const Value& a, const Value& b) {
  if (a.IsNumber() && b.IsNumber()) {
    if (a.IsIntLike() && b.IsIntLike()) return AsInt(a) == AsInt(b);
    return AsDouble(a) == AsDouble(b);
  }
  if (a.type == Value::Type::kComplex || b.type == Value::Type::kComplex) {
    const auto parts = [](const Value& v) {
      return v.type == Value::Type::kComplex ? std::make_pair(v.f, v.imag) : std::make_pair(AsDouble(v), 0.0);
    };
    const bool numbers = (a.IsNumber() || a.type == Value::Type::kComplex) && (b.IsNumber() || b.type == Value::Type::kComplex);
    return numbers && parts(a) == parts(b);
  }
  if (a.IsAnySet() && b.IsAnySet()) return SetOf(a).size() == SetOf(b).size() && IsSubset(a, b);
  const bool seq = a.IsSequence() && b.IsSequence();
  if (a.type != b.type && !seq) return false;
  if (seq && a.type != b.type) return false;
  switch (a.type) {
    case Value::Type::kNone: return true;
    case Value::Type::kStr: return a.s == b.s;
    case Value::Type::kList:
    case Value::Type::kTuple: {
      if (a.list->size() != b.list->size()) return false;
      for (size_t k = 0; k < a.list->size(); ++k) {
        if (!Equal((*a.list)[k], (*b.list)[k])) return false;
      }
      return true;
    }
    case Value::Type::kDict: {
      if (a.dict->items.size() != b.dict->items.size()) return false;
      for (const auto& [key, value] : a.dict->items) {
        const size_t k = b.dict->Find(key);
        if (k == DictItems::kNone || !Equal(value, b.dict->items[k].second)) return false;
      }
      return true;
    }
    case Value::Type::kRange: return RangeEqual(a, b);
    case Value::Type::kSlice: {
      for (size_t k = 0; k < 3; ++k) {
        if (!Equal((*a.list)[k], (*b.list)[k])) return false;
      }
      return true;
    }
    case Value::Type::kUnion: return UnionEqual(a, b);
    case Value::Type::kIterator:
    case Value::Type::kType:
    case Value::Type::kInstance: return a.object == b.object;
    case Value::Type::kFunction: return a.fn == b.fn;
    case Value::Type::kModule: return a.dict == b.dict;
    case Value::Type::kScope: return a.scope == b.scope;
    case Value::Type::kBlock: return a.block == b.block;
    default: return false;
  }
}

int Compare(const Value& a, const Value& b, const char* op) {
  if (a.IsNumber() && b.IsNumber()) {
    if (a.IsIntLike() && b.IsIntLike()) {
      const Int x = AsInt(a), y = AsInt(b);
      return x < y ? -1 : (x > y ? 1 : 0);
    }
    const double x = AsDouble(a), y = AsDouble(b);
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (a.type == Value::Type::kStr && b.type == Value::Type::kStr) {
    const int c = a.s.compare(b.s);
    return c < 0 ? -1 : (c > 0 ? 1 : 0);
  }
  if ((a.IsSequence() || a.type == Value::Type::kSlice) && a.type == b.type) {
    const size_t n = std::min(a.list->size(), b.list->size());
    for (size_t k = 0; k < n; ++k) {
      if (!Equal((*a.list)[k], (*b.list)[k])) return Compare((*a.list)[k], (*b.list)[k], op);
    }
    return a.list->size() < b.list->size() ? -1 : (a.list->size() > b.list->size() ? 1 : 0);
  }
  throw EvalError(std::string("'") + op + "' not supported between instances of '" + TypeName(a) +
                  "' and '" + TypeName(b) + "'");
}

bool RichCompare(const std::string& op, const Value& a, const Value& b) {
  if (a.IsAnySet() && b.IsAnySet()) {
    // subset order
    const size_t na = SetOf(a).size(), nb = SetOf(b).size();
    if (op == "<") return na < nb && IsSubset(a, b);
    if (op == "<=") return IsSubset(a, b);
    if (op == ">") return na > nb && IsSuperset(a, b);
    return IsSuperset(a, b);
  }
  const int c = Compare(a, b, op.c_str());
  if (op == "<") return c < 0;
  if (op == ">") return c > 0;
  if (op == "<=") return c <= 0;
  return c >= 0;
}

Value CallValue(const Value& f, ValueList args, Kwargs kwargs) {
  if (!f.IsCallable()) throw EvalError("'" + TypeName(f) + "' object is not callable");
  return f.fn->call(args, kwargs);
}

size_t DictItems::Find(const Value& key) const {
  constexpr size_t kLinear = 8;  // small dicts are searched, large ones indexed
  if (items.size() <= kLinear) {
    Hash(key);  // Python hashes the key first: unhashable keys are errors
    for (size_t k = 0; k < items.size(); ++k) {
      if (Equal(items[k].first, key)) return k;
    }
    return kNone;
  }
  if (!indexed_) {
    for (size_t k = 0; k < items.size(); ++k) index_.emplace(Hash(items[k].first), k);
    indexed_ = true;
  }
  const auto [begin, end] = index_.equal_range(Hash(key));
  for (auto it = begin; it != end; ++it) {
    if (Equal(items[it->second].first, key)) return it->second;
  }
  return kNone;
}

std::vector<std::pair<Value, Value>> DictBuilder::Take() { return std::move(items_); }

void DictBuilder::Put(Value key, Value value) {
  const int64_t hash = Hash(key);
  const auto [begin, end] = index_.equal_range(hash);
  for (auto it = begin; it != end; ++it) {
    if (Equal(items_[it->second].first, key)) {
      items_[it->second].second = std::move(value);
      return;
    }
  }
  index_.emplace(hash, items_.size());
  items_.emplace_back(std::move(key), std::move(value));
}

Value Wrapped(Value v, bool wrap) {
  if (wrap && (v.type == Value::Type::kDict || v.type == Value::Type::kList)) v.wrapped = true;
  return v;
}

NextFunction IterateLazily(const Value& v) {
  switch (v.type) {
    case Value::Type::kList:
    case Value::Type::kTuple: {
      CheckListSize(static_cast<Int>(v.list->size()), "sequence");
      return [list = v.list, wrap = v.wrapped, k = size_t{0}]() mutable -> std::optional<Value> {
        if (k == list->size()) return std::nullopt;
        return Wrapped((*list)[k++], wrap);
      };
    }
    case Value::Type::kStr: {
      // one item per UTF-8 code point
      const auto length = [s = &v.s](size_t k) {
        const unsigned char c = (*s)[k];
        return c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc0 ? 2 : 1;
      };
      Int count = 0;
      for (size_t k = 0; k < v.s.size(); k += length(k)) ++count;
      CheckListSize(count, "string to iterate");
      return [s = v.s, k = size_t{0}]() mutable -> std::optional<Value> {
        if (k >= s.size()) return std::nullopt;
        const unsigned char c = s[k];
        const size_t n = c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc0 ? 2 : 1;
        Value item = Value::Str(s.substr(k, n));
        k += n;
        return item;
      };
    }
    case Value::Type::kDict: {
      CheckListSize(static_cast<Int>(v.dict->items.size()), "dict");
      return [dict = v.dict, k = size_t{0}]() mutable -> std::optional<Value> {
        if (k == dict->items.size()) return std::nullopt;
        return dict->items[k++].first;
      };
    }
    case Value::Type::kSet:
    case Value::Type::kFrozenSet: {
      // the keys as they are now (CPython raises if a set changes size while it is iterated)
      auto keys = std::make_shared<ValueList>(SetOf(v).Keys());
      CheckListSize(static_cast<Int>(keys->size()), "set");
      return [keys, k = size_t{0}]() mutable -> std::optional<Value> {
        if (k == keys->size()) return std::nullopt;
        return (*keys)[k++];
      };
    }
    case Value::Type::kRange: return IterateRange(v);
    case Value::Type::kIterator:
      return [it = v.object]() { return static_cast<Iterator&>(*it).Next(); };
    default: throw EvalError("'" + TypeName(v) + "' object is not iterable");
  }
}

bool IsIterable(const Value& v) {
  switch (v.type) {
    case Value::Type::kList:
    case Value::Type::kTuple:
    case Value::Type::kStr:
    case Value::Type::kDict:
    case Value::Type::kSet:
    case Value::Type::kFrozenSet:
    case Value::Type::kRange:
    case Value::Type::kIterator: return true;
    default: return false;
  }
}

ValueList Iterate(const Value& v) {
  if (v.IsSequence() && !v.wrapped) {
    CheckListSize(static_cast<Int>(v.list->size()), "sequence");
    return *v.list;
  }
  const NextFunction next = IterateLazily(v);
  ValueList out;
  while (std::optional<Value> item = next()) {
    if (out.size() == kMaxListItems) CheckListSize(static_cast<Int>(out.size() + 1), "iterator");
    out.push_back(std::move(*item));
  }
  return out;
}

}  // namespace urdfsnap::xacro
