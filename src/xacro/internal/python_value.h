// Python values as xacro's `${}` expressions see them (None, bool, int, float, complex, str, list,
// tuple, dict, set, frozenset, range, slice, iterators, types, callables, modules, property scopes
// and XML blocks) and the Python rules for them: str() and repr(), truth, equality, ordering and
// iteration.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace urdfsnap::xacro {

class Table;
struct Node;

// Python's int, exact up to 127 bits (beyond that an operation raises OverflowError).
using Int = __int128;

// A Python exception raised while evaluating an expression; what() is the message Python prints
// (e.g. "name 'x' is not defined", "division by zero").
class EvalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Value;
using ValueList = std::vector<Value>;
using Kwargs = std::vector<std::pair<std::string, Value>>;

// An ordered dict (insertion order, as Python 3.7+). Dicts do not change once made.
struct DictItems {
  std::vector<std::pair<Value, Value>> items;

  // The position of the item whose key equals `key` (Python's lookup: hash, then ==), or kNone;
  // EvalError "unhashable type: 'list'" for an unhashable key. A large dict is indexed by hash on
  // its first lookup, so that looking up every key stays linear.
  size_t Find(const Value& key) const;
  static constexpr size_t kNone = SIZE_MAX;

 private:
  mutable std::unordered_multimap<int64_t, size_t> index_;
  mutable bool indexed_ = false;
};

// Builds a dict's items as Python fills a dict: a key equal to an earlier one replaces that
// item's value in its place (keys must be hashable: EvalError otherwise).
class DictBuilder {
 public:
  void Put(Value key, Value value);
  std::vector<std::pair<Value, Value>> Take();

 private:
  std::vector<std::pair<Value, Value>> items_;
  std::unordered_multimap<int64_t, size_t> index_;
};

// A callable: a builtin function, a method bound to its receiver, or a type's constructor.
struct Function {
  std::string name;
  std::function<Value(ValueList& args, Kwargs& kwargs)> call;
  std::string repr;  // when not "<built-in function NAME>"
};

// The shared state of the values that are more than a payload: a set's hash table
// (python_set.h), an iterator's position (python_iterators.h), a type (python_types.h).
struct Object {
  virtual ~Object() = default;
};

// The text of a str value, shared by every copy of the value: Python's str is immutable, and
// copying a value (into a list, a comprehension's variable, a property) must not copy its text,
// which may be megabytes long. Reads as a const std::string.
class SharedString {
 public:
  SharedString() = default;
  SharedString(std::string text);  // NOLINT(google-explicit-constructor): a str is made from text
  SharedString(const char* text) : SharedString(std::string(text)) {}  // NOLINT

  const std::string& str() const { return text_ ? *text_ : Empty(); }
  operator const std::string&() const { return str(); }  // NOLINT

  // the read-only std::string interface the evaluator uses
  size_t size() const { return str().size(); }
  bool empty() const { return str().empty(); }
  const char* c_str() const { return str().c_str(); }
  char operator[](size_t k) const { return str()[k]; }
  std::string::const_iterator begin() const { return str().begin(); }
  std::string::const_iterator end() const { return str().end(); }
  std::string substr(size_t pos, size_t n = std::string::npos) const { return str().substr(pos, n); }
  size_t find(std::string_view what, size_t pos = 0) const { return str().find(what, pos); }
  size_t find(char c, size_t pos = 0) const { return str().find(c, pos); }
  int compare(const std::string& other) const { return str().compare(other); }
  friend bool operator==(const SharedString& a, const std::string& b) { return a.str() == b; }
  friend bool operator==(const SharedString& a, const char* b) { return a.str() == b; }
  friend bool operator==(const SharedString& a, const SharedString& b) { return a.str() == b.str(); }
  template <class T>
  friend bool operator!=(const SharedString& a, const T& b) { return !(a == b); }
  friend std::string operator+(const SharedString& a, const std::string& b) { return a.str() + b; }
  friend std::string operator+(const std::string& a, const SharedString& b) { return a + b.str(); }
  friend std::string operator+(const char* a, const SharedString& b) { return a + b.str(); }
  friend std::string operator+(const SharedString& a, const char* b) { return a.str() + b; }

 private:
  static const std::string& Empty();
  std::shared_ptr<const std::string> text_;
};

struct Value {
  enum class Type {
    kNone, kBool, kInt, kFloat, kComplex, kStr, kList, kTuple, kDict, kSet, kFrozenSet, kRange,
    kSlice, kIterator, kType, kUnion, kInstance, kFunction, kModule, kScope, kBlock
  };

  Type type = Type::kNone;
  // a yaml dict or list (xacro's YamlDictWrapper/YamlListWrapper): dict keys read as attributes,
  // nested dicts and lists read from it are wrapped too
  bool wrapped = false;
  bool b = false;
  Int i = 0;
  double f = 0.0;                      // float; a complex number's real part
  double imag = 0.0;                   // a complex number's imaginary part
  SharedString s;                      // str value; module name
  std::shared_ptr<ValueList> list;     // list and tuple items; range (start, stop, step) and
                                       // slice (start, stop, step); a union's types
  std::shared_ptr<DictItems> dict;     // dict items; module members
  std::shared_ptr<Function> fn;        // callable (a type's constructor too)
  std::shared_ptr<Object> object;      // set/frozenset table, iterator, type, instance's class
  std::shared_ptr<Table> scope;        // property namespace of an include with ns=
  const Node* block = nullptr;         // XML block of a *param or a block property

  static Value None() { return {}; }
  static Value Bool(bool v);
  static Value Integer(Int v);
  static Value Float(double v);
  static Value Complex(double real, double imag);
  static Value Str(std::string v);
  static Value List(ValueList items);
  static Value Tuple(ValueList items);
  static Value Dict(std::vector<std::pair<Value, Value>> items);
  // range(start, stop, step); step != 0
  static Value Range(Int start, Int stop, Int step);
  // slice(start, stop, step) of any values
  static Value SliceOf(Value start, Value stop, Value step);
  static Value Module(std::string name, std::vector<std::pair<Value, Value>> members);
  static Value Callable(std::string name, std::function<Value(ValueList&, Kwargs&)> call);
  static Value Scope(std::shared_ptr<Table> table);
  static Value Block(const Node* node);

  bool IsNumber() const { return type == Type::kBool || type == Type::kInt || type == Type::kFloat; }
  bool IsIntLike() const { return type == Type::kBool || type == Type::kInt; }
  bool IsSequence() const { return type == Type::kList || type == Type::kTuple; }
  bool IsAnySet() const { return type == Type::kSet || type == Type::kFrozenSet; }
  // whether calling it means anything (functions, methods, types)
  bool IsCallable() const { return fn != nullptr; }
};

// Python's type(v).__name__ ("int", "str", "NoneType", ...).
std::string TypeName(const Value& v);

// Python's str(v) and repr(v).
std::string ToStr(const Value& v);
std::string Repr(const Value& v);

// Python's bool(v).
bool Truthy(const Value& v);

// Python's int value of a bool or int; the value as a double for any number.
Int AsInt(const Value& v);
double AsDouble(const Value& v);

// Python's a == b.
bool Equal(const Value& a, const Value& b);

// Python's ordering: negative, zero or positive; throws EvalError ("'<' not supported between
// instances of 'str' and 'int'") for values Python cannot order.
int Compare(const Value& a, const Value& b, const char* op = "<");

// Python's `a OP b` for OP in < <= > >=, sets included (subset order, which is partial).
bool RichCompare(const std::string& op, const Value& a, const Value& b);

// Calls a callable value; EvalError "'int' object is not callable" for anything else.
Value CallValue(const Value& f, ValueList args, Kwargs kwargs = {});

// Python's iter(v) as a pull function giving the items one by one and nullopt at the end:
// list, tuple, str (code points), dict (keys), set, range and iterator items, wrapped when the
// container is. Containers are checked against kMaxListItems and charged to the evaluation
// budget up front (an iterator's items come from such a container; see evaluation_budget.h).
// Throws "'int' object is not iterable".
using NextFunction = std::function<std::optional<Value>()>;
NextFunction IterateLazily(const Value& v);

// Whether IterateLazily takes v.
bool IsIterable(const Value& v);

// All the items of an iterable value (an iterator is used up), at most kMaxListItems.
ValueList Iterate(const Value& v);

// A value read from a wrapped (yaml) container is wrapped in turn.
Value Wrapped(Value v, bool wrap);

}  // namespace urdfsnap::xacro
