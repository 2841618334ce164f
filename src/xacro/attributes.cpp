// Python attribute access and the methods of the builtin types that xacro files use.
#include "xacro/internal/attributes.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "xacro/internal/call_arguments.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/operators.h"
#include "xacro/internal/python_iterators.h"
#include "xacro/internal/python_set.h"
#include "xacro/internal/python_types.h"
#include "xacro/internal/symbol_table.h"

namespace urdfsnap::xacro {

void CheckArity(const std::string& function, const ValueList& args, size_t min, size_t max) {
  if (args.size() < min || args.size() > max) {
    throw EvalError(function + "() takes " + (min == max ? "exactly " + std::to_string(min) :
                                              "from " + std::to_string(min) + " to " + std::to_string(max)) +
                    " arguments (" + std::to_string(args.size()) + " given)");
  }
}

const std::string& StrArg(const std::string& function, const ValueList& args, size_t index) {
  if (args[index].type != Value::Type::kStr) {
    throw EvalError(function + "() argument must be str, not " + TypeName(args[index]));
  }
  return args[index].s;
}

namespace {

const char* const kSpace = " \t\n\r\f\v";

Value Bind(const std::string& name, std::function<Value(ValueList&)> body) {
  return Value::Callable(name, [name, body = std::move(body)](ValueList& args, Kwargs& kwargs) {
    if (!kwargs.empty()) throw EvalError(name + "() takes no keyword arguments");
    return body(args);
  });
}

ValueList Split(const std::string& s, const Value* sep, long maxsplit, bool from_right) {
  ValueList parts;
  if (!sep || sep->type == Value::Type::kNone) {
    std::vector<std::string> words;
    size_t k = 0;
    while (true) {
      k = s.find_first_not_of(kSpace, k);
      if (k == std::string::npos) break;
      const size_t e = s.find_first_of(kSpace, k);
      words.push_back(s.substr(k, e == std::string::npos ? std::string::npos : e - k));
      if (e == std::string::npos) break;
      k = e;
    }
    if (maxsplit >= 0 && static_cast<long>(words.size()) > maxsplit + 1) {
      // rejoining keeps it simple: re-split with the original text
      std::vector<std::string> limited;
      if (!from_right) {
        size_t pos = 0;
        for (long n = 0; n < maxsplit; ++n) {
          pos = s.find_first_not_of(kSpace, pos);
          const size_t e = s.find_first_of(kSpace, pos);
          limited.push_back(s.substr(pos, e - pos));
          pos = e;
        }
        pos = s.find_first_not_of(kSpace, pos);
        limited.push_back(s.substr(pos, s.find_last_not_of(kSpace) - pos + 1));
        words = limited;
      } else {
        std::vector<std::string> tail(words.end() - maxsplit, words.end());
        size_t end = s.size();
        for (long n = 0; n < maxsplit; ++n) {
          end = s.find_last_not_of(kSpace, end - 1);
          end = s.find_last_of(kSpace, end);
        }
        const size_t b = s.find_first_not_of(kSpace);
        limited.push_back(s.substr(b, s.find_last_not_of(kSpace, end) - b + 1));
        limited.insert(limited.end(), tail.begin(), tail.end());
        words = limited;
      }
    }
    for (auto& w : words) parts.push_back(Value::Str(w));
    return parts;
  }
  if (sep->type != Value::Type::kStr) throw EvalError("must be str or None, not " + TypeName(*sep));
  if (sep->s.empty()) throw EvalError("empty separator");
  std::vector<std::string> pieces;
  size_t k = 0;
  while (true) {
    const size_t e = s.find(sep->s, k);
    if (e == std::string::npos) {
      pieces.push_back(s.substr(k));
      break;
    }
    pieces.push_back(s.substr(k, e - k));
    k = e + sep->s.size();
  }
  if (maxsplit >= 0 && static_cast<long>(pieces.size()) > maxsplit + 1) {
    std::vector<std::string> limited;
    if (!from_right) {
      limited.assign(pieces.begin(), pieces.begin() + maxsplit);
      std::string rest;
      for (size_t n = static_cast<size_t>(maxsplit); n < pieces.size(); ++n) rest += (n > static_cast<size_t>(maxsplit) ? sep->s : "") + pieces[n];
      limited.push_back(rest);
    } else {
      std::string rest;
      const size_t keep = pieces.size() - static_cast<size_t>(maxsplit);
      for (size_t n = 0; n < keep; ++n) rest += (n ? sep->s : "") + pieces[n];
      limited.push_back(rest);
      limited.insert(limited.end(), pieces.begin() + static_cast<long>(keep), pieces.end());
    }
    pieces = limited;
  }
  for (auto& p : pieces) parts.push_back(Value::Str(p));
  return parts;
}

std::string Strip(const std::string& s, const ValueList& args, bool left, bool right) {
  const std::string chars = args.empty() || args[0].type == Value::Type::kNone ? kSpace : args[0].s;
  size_t b = 0, e = s.size();
  if (left) {
    b = s.find_first_not_of(chars);
    if (b == std::string::npos) return "";
  }
  if (right) {
    const size_t last = s.find_last_not_of(chars);
    if (last == std::string::npos) return "";
    e = last + 1;
  }
  return b < e ? s.substr(b, e - b) : "";
}

std::string MapChars(std::string s, int (*f)(int)) {
  for (char& c : s) c = static_cast<char>(f(static_cast<unsigned char>(c)));
  return s;
}

bool AllChars(const std::string& s, int (*f)(int)) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [f](char c) { return f(static_cast<unsigned char>(c)) != 0; });
}

// One call of a str method: the text (shared with the str value: a bound method does not copy
// it), the method's name (for its messages), the arguments.
struct StrCall {
  const SharedString& s;
  const std::string& name;
  ValueList& a;
  Kwargs& kw;
};

Value StrUpper(const StrCall& c) {
  return Value::Str(MapChars(c.s, ::toupper));
}

Value StrLower(const StrCall& c) {
  return Value::Str(MapChars(c.s, ::tolower));
}

Value StrCapitalize(const StrCall& c) {
  std::string r = MapChars(c.s, ::tolower);
  if (!r.empty()) r[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(r[0])));
  return Value::Str(r);
}

Value StrTitle(const StrCall& c) {
  std::string r = c.s;
  bool start = true;
  for (char& c : r) {
    const bool alpha = std::isalpha(static_cast<unsigned char>(c));
    c = static_cast<char>(start ? std::toupper(static_cast<unsigned char>(c)) : std::tolower(static_cast<unsigned char>(c)));
    start = !alpha;
  }
  return Value::Str(r);
}

Value StrSwapCase(const StrCall& c) {
  std::string r = c.s;
  for (char& c : r) {
    const unsigned char u = static_cast<unsigned char>(c);
    c = static_cast<char>(std::isupper(u) ? std::tolower(u) : std::toupper(u));
  }
  return Value::Str(r);
}

Value StrStrip(const StrCall& c) {
  CheckArity(c.name, c.a, 0, 1);
  return Value::Str(Strip(c.s, c.a, c.name != "rstrip", c.name != "lstrip"));
}

Value StrSplit(const StrCall& c) {
  const Value* sep = c.a.empty() ? nullptr : &c.a[0];
  long maxsplit = c.a.size() > 1 ? AsIndex(c.a[1], "maxsplit") : -1;
  for (auto& [k, v] : c.kw) {
    if (k == "sep") sep = &v;
    else if (k == "maxsplit") maxsplit = AsIndex(v, "maxsplit");
    else throw EvalError(c.name + "() got an unexpected keyword argument '" + k + "'");
  }
  return Value::List(Split(c.s, sep, maxsplit, c.name == "rsplit"));
}

Value StrSplitLines(const StrCall& c) {
  ValueList out;
  size_t k = 0;
  while (k < c.s.size()) {
    size_t e = c.s.str().find_first_of("\r\n", k);
    if (e == std::string::npos) e = c.s.size();
    out.push_back(Value::Str(c.s.substr(k, e - k)));
    k = e + ((e + 1 < c.s.size() && c.s[e] == '\r' && c.s[e + 1] == '\n') ? 2 : 1);
  }
  return Value::List(out);
}

Value StrJoin(const StrCall& c) {
  CheckArity("join", c.a, 1, 1);
  const ValueList items = Iterate(c.a[0]);
  // the size first, so that nothing too large is built
  size_t size = items.empty() ? 0 : c.s.size() * (items.size() - 1);
  for (size_t k = 0; k < items.size(); ++k) {
    if (items[k].type != Value::Type::kStr) {
      throw EvalError("sequence item " + std::to_string(k) + ": expected str instance, " + TypeName(items[k]) + " found");
    }
    size += items[k].s.size();
    if (size > kMaxStringBytes) break;
  }
  CheckStringSize(size, "joined string");
  std::string out;
  out.reserve(size);
  for (size_t k = 0; k < items.size(); ++k) {
    if (k) out += c.s.str();
    out += items[k].s.str();
  }
  return Value::Str(std::move(out));
}

Value StrReplace(const StrCall& c) {
  CheckArity("replace", c.a, 2, 3);
  const std::string& from = StrArg("replace", c.a, 0);
  const std::string& to = StrArg("replace", c.a, 1);
  const long limit = c.a.size() > 2 ? AsIndex(c.a[2], "count") : -1;
  // the number of replacements first, so that nothing too large is built
  size_t matches = 0;
  if (from.empty()) {
    matches = c.s.size() + 1;
  } else {
    for (size_t e = c.s.find(from); e != std::string::npos; e = c.s.find(from, e + from.size())) ++matches;
  }
  if (limit >= 0) matches = std::min(matches, static_cast<size_t>(limit));
  // (no overflow: each size is at most kMaxStringBytes)
  const size_t size = c.s.size() - matches * from.size() + matches * to.size();
  CheckStringSize(size, "replaced string");
  std::string out;
  out.reserve(size);
  size_t k = 0;
  for (size_t n = 0; n < matches; ++n) {
    if (from.empty()) {
      out += to;
      if (k < c.s.size()) out += c.s[k++];
      continue;
    }
    const size_t e = c.s.find(from, k);
    out.append(c.s.str(), k, e - k);
    out += to;
    k = e + from.size();
  }
  out.append(c.s.str(), k, std::string::npos);
  return Value::Str(std::move(out));
}

Value StrStartsOrEndsWith(const StrCall& c) {
  CheckArity(c.name, c.a, 1, 1);
  ValueList options = c.a[0].type == Value::Type::kTuple ? *c.a[0].list : ValueList{c.a[0]};
  for (const Value& o : options) {
    if (o.type != Value::Type::kStr) throw EvalError(c.name + " first arg must be str or a tuple of str");
    if (o.s.size() > c.s.size()) continue;
    const std::string& text = c.s;
    if (c.name == "startswith" ? text.compare(0, o.s.size(), o.s) == 0 : text.compare(c.s.size() - o.s.size(), o.s.size(), o.s) == 0) {
      return Value::Bool(true);
    }
  }
  return Value::Bool(false);
}

Value StrFindOrCount(const StrCall& c) {
  CheckArity(c.name, c.a, 1, 1);
  const std::string& sub = StrArg(c.name, c.a, 0);
  if (c.name == "count") {
    if (sub.empty()) return Value::Integer(static_cast<Int>(c.s.size() + 1));
    Int n = 0;
    for (size_t k = c.s.find(sub); k != std::string::npos; k = c.s.find(sub, k + sub.size())) ++n;
    return Value::Integer(n);
  }
  const size_t k = c.name[0] == 'r' ? c.s.str().rfind(sub) : c.s.find(sub);
  if (k == std::string::npos) {
    if (c.name == "index" || c.name == "rindex") throw EvalError("substring not found");
    return Value::Integer(-1);
  }
  return Value::Integer(static_cast<Int>(k));
}

Value StrPad(const StrCall& c) {
  CheckArity(c.name, c.a, 1, 2);
  const long width = AsIndex(c.a[0], "width");
  if (width > static_cast<long>(c.s.size())) CheckStringSize(static_cast<size_t>(width), "padded string");
  const char fill = c.name == "zfill" ? '0' : (c.a.size() > 1 ? StrArg(c.name, c.a, 1)[0] : ' ');
  if (width <= static_cast<long>(c.s.size())) return Value::Str(c.s);
  const size_t pad = static_cast<size_t>(width) - c.s.size();
  if (c.name == "ljust") return Value::Str(c.s + std::string(pad, fill));
  if (c.name == "rjust") return Value::Str(std::string(pad, fill) + c.s);
  if (c.name == "center") {
    const size_t left = pad / 2 + (pad & static_cast<size_t>(width) & 1);
    return Value::Str(std::string(left, fill) + c.s + std::string(pad - left, fill));
  }
  const bool signed_ = !c.s.empty() && (c.s[0] == '-' || c.s[0] == '+');
  return Value::Str(signed_ ? c.s.substr(0, 1) + std::string(pad, '0') + c.s.substr(1) : std::string(pad, '0') + c.s);
}

Value StrIsDigit(const StrCall& c) {
  return Value::Bool(AllChars(c.s, ::isdigit));
}

Value StrIsAlpha(const StrCall& c) {
  return Value::Bool(AllChars(c.s, ::isalpha));
}

Value StrIsAlnum(const StrCall& c) {
  return Value::Bool(AllChars(c.s, ::isalnum));
}

Value StrIsSpace(const StrCall& c) {
  return Value::Bool(AllChars(c.s, ::isspace));
}

Value StrIsUpper(const StrCall& c) {
  return Value::Bool(std::any_of(c.s.begin(), c.s.end(), ::isupper) && !std::any_of(c.s.begin(), c.s.end(), ::islower));
}

Value StrIsLower(const StrCall& c) {
  return Value::Bool(std::any_of(c.s.begin(), c.s.end(), ::islower) && !std::any_of(c.s.begin(), c.s.end(), ::isupper));
}

// Python's str methods by name: the body, and whether it takes keyword arguments.
const std::map<std::string, std::pair<Value (*)(const StrCall&), bool>>& StrMethods() {
  static const std::map<std::string, std::pair<Value (*)(const StrCall&), bool>> methods = {
      {"upper", {StrUpper, false}},
      {"lower", {StrLower, false}},
      {"capitalize", {StrCapitalize, false}},
      {"title", {StrTitle, false}},
      {"swapcase", {StrSwapCase, false}},
      {"strip", {StrStrip, false}},
      {"lstrip", {StrStrip, false}},
      {"rstrip", {StrStrip, false}},
      {"split", {StrSplit, true}},
      {"rsplit", {StrSplit, true}},
      {"splitlines", {StrSplitLines, false}},
      {"join", {StrJoin, false}},
      {"replace", {StrReplace, false}},
      {"startswith", {StrStartsOrEndsWith, false}},
      {"endswith", {StrStartsOrEndsWith, false}},
      {"find", {StrFindOrCount, false}},
      {"rfind", {StrFindOrCount, false}},
      {"index", {StrFindOrCount, false}},
      {"rindex", {StrFindOrCount, false}},
      {"count", {StrFindOrCount, false}},
      {"zfill", {StrPad, false}},
      {"ljust", {StrPad, false}},
      {"rjust", {StrPad, false}},
      {"center", {StrPad, false}},
      {"isdigit", {StrIsDigit, false}},
      {"isalpha", {StrIsAlpha, false}},
      {"isalnum", {StrIsAlnum, false}},
      {"isspace", {StrIsSpace, false}},
      {"isupper", {StrIsUpper, false}},
      {"islower", {StrIsLower, false}},
  };
  return methods;
}

Value StrMethod(const SharedString& s, const std::string& name) {
  const auto method = StrMethods().find(name);
  if (method == StrMethods().end()) throw EvalError("'str' object has no attribute '" + name + "'");
  // copies, not structured bindings: clang 14 (the sanitizer build's) cannot capture those
  const auto body = method->second.first;
  const bool keywords = method->second.second;
  const std::string full = "str." + name;
  return Value::Callable(full, [s, name, full, body, keywords](ValueList& a, Kwargs& kw) {
    if (!keywords && !kw.empty()) throw EvalError(full + "() takes no keyword arguments");
    return body({s, name, a, kw});
  });
}

Value SequenceMethod(const Value& v, const std::string& name) {
  const std::string type = TypeName(v);
  if (name == "index" || name == "count") {
    return Bind(type + "." + name, [v, name](ValueList& a) {
      CheckArity(name, a, 1, 1);
      Int n = 0;
      for (size_t k = 0; k < v.list->size(); ++k) {
        if (!Equal((*v.list)[k], a[0])) continue;
        if (name == "index") return Value::Integer(static_cast<Int>(k));
        ++n;
      }
      if (name == "index") throw EvalError(Repr(a[0]) + " is not in " + TypeName(v));
      return Value::Integer(n);
    });
  }
  throw EvalError("'" + type + "' object has no attribute '" + name + "'");
}

Value DictMethod(const Value& v, const std::string& name) {
  if (name == "keys" || name == "values" || name == "items") {
    return Bind("dict." + name, [v, name](ValueList& a) {
      CheckArity(name, a, 0, 0);
      ValueList out;
      for (const auto& [key, value] : v.dict->items) {
        if (name == "keys") out.push_back(key);
        else if (name == "values") out.push_back(Wrapped(value, v.wrapped));
        else out.push_back(Value::Tuple({key, Wrapped(value, v.wrapped)}));
      }
      return Value::List(out);
    });
  }
  if (name == "get") {
    return Bind("dict.get", [v](ValueList& a) {
      CheckArity("get", a, 1, 2);
      const size_t k = v.dict->Find(a[0]);
      if (k != DictItems::kNone) return Wrapped(v.dict->items[k].second, v.wrapped);
      return a.size() > 1 ? a[1] : Value::None();
    });
  }
  if (name == "copy") return Bind("dict.copy", [v](ValueList&) { return Value::Dict(v.dict->items); });
  throw EvalError("'dict' object has no attribute '" + name + "'");
}

// the method, with the text of each result charged to the evaluation budget: a method of a str
// makes new text (bounded by its own, but a loop of them would grow without bound)
Value ChargingText(Value method) {
  const std::shared_ptr<Function> inner = method.fn;
  method.fn = std::make_shared<Function>(Function{inner->name, [inner](ValueList& a, Kwargs& kw) {
    Value result = inner->call(a, kw);
    size_t bytes = result.type == Value::Type::kStr ? result.s.size() : 0;
    if (result.type == Value::Type::kList) {
      for (const Value& item : *result.list) bytes += item.type == Value::Type::kStr ? item.s.size() : 0;
    }
    EvaluationBudget::ChargeBytes(bytes);
    return result;
  }, ""});
  return method;
}

// a method of a set or frozenset
Value SetMethod(const Value& v, const std::string& name) {
  const std::string full = TypeName(v) + "." + name;
  // methods of any number of iterables, or of exactly one
  const auto many = [&](Value (*body)(const Value&, ValueList&)) {
    return Value::Callable(name, [v, full, body](ValueList& a, Kwargs& kw) {
      NoKeywords(full, kw);
      return body(v, a);
    });
  };
  const auto one = [&](Value (*body)(const Value&, const Value&)) {
    return Value::Callable(name, [v, full, body](ValueList& a, Kwargs& kw) {
      NoKeywords(full, kw);
      TakesOne(full, a);
      return body(v, a[0]);
    });
  };
  const auto none = [&](Value (*body)(const Value&)) {
    return Value::Callable(name, [v, full, body](ValueList& a, Kwargs& kw) {
      NoKeywords(full, kw);
      if (!a.empty()) throw EvalError(full + "() takes no arguments (" + std::to_string(a.size()) + " given)");
      return body(v);
    });
  };
  if (name == "copy") {
    return none([](const Value& s) { return s.type == Value::Type::kFrozenSet ? s : SetCopy(s); });
  }
  if (name == "union") return many([](const Value& s, ValueList& a) { return SetUnion(s, a); });
  if (name == "intersection") {
    return many([](const Value& s, ValueList& a) {
      if (a.empty()) return SetCopy(s);
      Value r = s;
      for (const Value& other : a) r = SetIntersection(r, other);
      return r;
    });
  }
  if (name == "difference") {
    return many([](const Value& s, ValueList& a) {
      if (a.empty()) return SetCopy(s);
      Value r = SetDifference(s, a[0]);
      for (size_t k = 1; k < a.size(); ++k) SetDifferenceUpdate(r, a[k]);
      return r;
    });
  }
  if (name == "symmetric_difference") return one(SetSymmetricDifference);
  if (name == "issubset") return one([](const Value& s, const Value& o) { return Value::Bool(IsSubset(s, o)); });
  if (name == "issuperset") return one([](const Value& s, const Value& o) { return Value::Bool(IsSuperset(s, o)); });
  if (name == "isdisjoint") return one([](const Value& s, const Value& o) { return Value::Bool(IsDisjoint(s, o)); });
  if (v.type == Value::Type::kSet) {
    // the methods that change the set
    if (name == "add") return one([](const Value& s, const Value& k) { SetOf(s).Add(k); return Value::None(); });
    if (name == "discard") return one([](const Value& s, const Value& k) { SetOf(s).Discard(k); return Value::None(); });
    if (name == "remove") {
      return one([](const Value& s, const Value& k) {
        if (!SetOf(s).Discard(k)) throw EvalError(Repr(k));
        return Value::None();
      });
    }
    if (name == "pop") return none([](const Value& s) { return SetOf(s).Pop(); });
    if (name == "clear") return none([](const Value& s) { SetOf(s).Clear(); return Value::None(); });
    if (name == "update") {
      return many([](const Value& s, ValueList& a) {
        for (const Value& other : a) SetOf(s).Update(other);
        return Value::None();
      });
    }
    if (name == "intersection_update") {
      return many([](const Value& s, ValueList& a) {
        Value r = s;
        for (const Value& other : a) r = SetIntersection(r, other);
        if (r.object != s.object) SetOf(s) = SetOf(r);
        return Value::None();
      });
    }
    if (name == "difference_update") {
      return many([](const Value& s, ValueList& a) {
        for (const Value& other : a) SetDifferenceUpdate(s, other);
        return Value::None();
      });
    }
    if (name == "symmetric_difference_update") {
      return one([](const Value& s, const Value& o) { SetSymmetricDifferenceUpdate(s, o); return Value::None(); });
    }
  }
  throw EvalError("'" + TypeName(v) + "' object has no attribute '" + name + "'");
}

Value RangeAttribute(const Value& v, const std::string& name) {
  if (name == "start") return (*v.list)[0];
  if (name == "stop") return (*v.list)[1];
  if (name == "step") return (*v.list)[2];
  if (name == "count" || name == "index") {
    return Value::Callable(name, [v, name](ValueList& a, Kwargs& kw) {
      NoKeywords("range." + name, kw);
      TakesOne("range." + name, a);
      const bool found = RangeContains(v, a[0]);
      if (name == "count") return Value::Integer(found ? 1 : 0);
      if (!found) throw EvalError(Repr(a[0]) + " is not in range");
      // the position of an equal item
      Int k = 0;
      const NextFunction next = IterateLazily(v);
      while (std::optional<Value> item = next()) {
        if (Equal(*item, a[0])) break;
        ++k;
      }
      return Value::Integer(k);
    });
  }
  throw EvalError("'range' object has no attribute '" + name + "'");
}

Value SliceAttribute(const Value& v, const std::string& name) {
  if (name == "start") return (*v.list)[0];
  if (name == "stop") return (*v.list)[1];
  if (name == "step") return (*v.list)[2];
  if (name == "indices") {
    return Bind("slice.indices", [v](ValueList& a) {
      TakesOne("slice.indices", a);
      if (!a[0].IsIntLike()) throw EvalError("'" + TypeName(a[0]) + "' object cannot be interpreted as an integer");
      return SliceIndicesTuple(v, AsInt(a[0]));
    });
  }
  throw EvalError("'slice' object has no attribute '" + name + "'");
}

}  // namespace

Value GetAttribute(const Value& v, const std::string& name) {
  switch (v.type) {
    case Value::Type::kModule:
      for (const auto& [key, member] : v.dict->items) {
        if (key.s == name) return member;
      }
      throw EvalError("module '" + v.s + "' has no attribute '" + name + "'");
    case Value::Type::kScope: return v.scope->Get(name);
    case Value::Type::kDict:
      if (v.wrapped) {
        const size_t k = v.dict->Find(Value::Str(name));
        if (k != DictItems::kNone) return Wrapped(v.dict->items[k].second, true);
        throw EvalError("The yaml dictionary has no key '" + name + "'");
      }
      return DictMethod(v, name);
    case Value::Type::kStr: return ChargingText(StrMethod(v.s, name));
    case Value::Type::kList:
    case Value::Type::kTuple: return SequenceMethod(v, name);
    case Value::Type::kSet:
    case Value::Type::kFrozenSet: return SetMethod(v, name);
    case Value::Type::kRange: return RangeAttribute(v, name);
    case Value::Type::kSlice: return SliceAttribute(v, name);
    case Value::Type::kType: return TypeAttribute(v, name);
    case Value::Type::kInstance: return InstanceAttribute(v, name);
    case Value::Type::kComplex:
      if (name == "real") return Value::Float(v.f);
      if (name == "imag") return Value::Float(v.imag);
      if (name == "conjugate") {
        return Bind("complex.conjugate", [re = v.f, im = v.imag](ValueList& a) {
          CheckArity("conjugate", a, 0, 0);
          return Value::Complex(re, -im);
        });
      }
      break;
    case Value::Type::kFloat:
      if (name == "is_integer") {
        return Bind("float.is_integer", [f = v.f](ValueList&) { return Value::Bool(std::isfinite(f) && f == static_cast<double>(static_cast<long long>(f))); });
      }
      if (name == "real") return v;
      if (name == "imag") return Value::Float(0.0);
      break;
    case Value::Type::kInt:
    case Value::Type::kBool:
      if (name == "real" || name == "numerator") return Value::Integer(AsInt(v));
      if (name == "imag") return Value::Integer(0);
      if (name == "denominator") return Value::Integer(1);
      break;
    default: break;
  }
  throw EvalError("'" + TypeName(v) + "' object has no attribute '" + name + "'");
}

}  // namespace urdfsnap::xacro
