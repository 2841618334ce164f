// Python values as xacro's `${}` expressions see them (None, bool, int, float, str, list, tuple,
// dict, callables, modules, property scopes and XML blocks) and the Python rules for them:
// str() and repr(), truth, equality and ordering.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
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

// An ordered dict (insertion order, as Python 3.7+).
struct DictItems {
  std::vector<std::pair<Value, Value>> items;
};

// A callable: a builtin function or a method bound to its receiver.
struct Function {
  std::string name;
  std::function<Value(ValueList& args, Kwargs& kwargs)> call;
};

struct Value {
  enum class Type { kNone, kBool, kInt, kFloat, kStr, kList, kTuple, kDict, kFunction, kModule, kScope, kBlock };

  Type type = Type::kNone;
  // a yaml dict or list (xacro's YamlDictWrapper/YamlListWrapper): dict keys read as attributes,
  // nested dicts and lists read from it are wrapped too
  bool wrapped = false;
  bool b = false;
  Int i = 0;
  double f = 0.0;
  std::string s;                       // str value; module name
  std::shared_ptr<ValueList> list;     // list and tuple items
  std::shared_ptr<DictItems> dict;     // dict items; module members
  std::shared_ptr<Function> fn;        // callable
  std::shared_ptr<Table> scope;        // property namespace of an include with ns=
  const Node* block = nullptr;         // XML block of a *param or a block property

  static Value None() { return {}; }
  static Value Bool(bool v);
  static Value Integer(Int v);
  static Value Float(double v);
  static Value Str(std::string v);
  static Value List(ValueList items);
  static Value Tuple(ValueList items);
  static Value Dict(std::vector<std::pair<Value, Value>> items);
  static Value Module(std::string name, std::vector<std::pair<Value, Value>> members);
  static Value Callable(std::string name, std::function<Value(ValueList&, Kwargs&)> call);
  static Value Scope(std::shared_ptr<Table> table);
  static Value Block(const Node* node);

  bool IsNumber() const { return type == Type::kBool || type == Type::kInt || type == Type::kFloat; }
  bool IsIntLike() const { return type == Type::kBool || type == Type::kInt; }
  bool IsSequence() const { return type == Type::kList || type == Type::kTuple; }
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

// The items of an iterable value (list, tuple, str, dict keys), wrapped when the container is.
ValueList Iterate(const Value& v);

// Sets `key` in ordered dict items: replaces the value of an equal key, else appends.
void DictPut(std::vector<std::pair<Value, Value>>& items, Value key, Value value);

// A value read from a wrapped (yaml) container is wrapped in turn.
Value Wrapped(Value v, bool wrap);

}  // namespace urdfsnap::xacro
