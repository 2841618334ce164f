// Python's type objects as expressions see them: `python.int`, `type(x)`, `isinstance`,
// `issubclass`, unions (`python.int | None`) and the classes `type(name, bases, dict)` makes.
// A type is a value of Value::Type::kType whose `fn` constructs its instances (python.int('3'))
// and whose `object` is its TypeObject.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

struct TypeObject : Object {
  std::string name;    // "int", "zip", "NameSpace", or a class's name
  std::string module;  // "" for builtins, else e.g. "xacro" or "types"
  Value base;          // the builtin base (int for bool, dict for a yaml dict); None: object
  // classes made by type(name, bases, dict)
  bool is_class = false;
  std::vector<Value> bases;
  std::vector<std::pair<std::string, Value>> attributes;
};

const TypeObject& TypeOf(const Value& type_value);

// The type named `name` ("int", "list_reverseiterator", "YamlDictWrapper", ...): the same value
// each time, so `type(1) is python.int`.
Value BuiltinType(const std::string& name);

// Python's type(v).
Value TypeOfValue(const Value& v);

// "<class 'int'>", "<class 'xacro.NameSpace'>", "<class 'X'>"; a union: "int | None".
std::string TypeRepr(const Value& t);

// Python's isinstance(v, classinfo) and issubclass(cls, classinfo), classinfo being a type, a
// union or a (nested) tuple of them; EvalError with Python's TypeError messages otherwise.
bool IsInstance(const Value& v, const Value& classinfo);
bool IsSubclass(const Value& cls, const Value& classinfo);

// `a | b` of types and None: a union (a lone type when both are the same).
Value TypeUnion(const Value& a, const Value& b);
// union == union: the same types
bool UnionEqual(const Value& a, const Value& b);

// type(name, bases, dict): a class whose instances read the dict's entries as attributes.
Value MakeClass(const Value& name, const Value& bases, const Value& dict);

// Attribute `name` of a type: a class's attribute, or a builtin type's method unbound
// (python.str.upper('a')); EvalError "type object 'str' has no attribute 'x'".
Value TypeAttribute(const Value& type, const std::string& name);

// An attribute of an instance of a class made by type(); EvalError when it has none.
Value InstanceAttribute(const Value& instance, const std::string& name);

// "<X object at 0x...>"
std::string InstanceRepr(const Value& instance);

// A builtin type's constructor, called with Python's arguments. Defined with the builtins
// (type_constructors.cpp); a type without one raises "cannot create 'X' instances".
struct TypeConstructor {
  const char* name;
  const char* module;
  const char* base;
  Value (*construct)(ValueList& args, Kwargs& kwargs);
};
const std::vector<TypeConstructor>& BuiltinTypeTable();

}  // namespace urdfsnap::xacro
