// Type objects: the registry of builtin types, type(), isinstance/issubclass, unions and the
// classes of type(name, bases, dict).
#include "xacro/internal/python_types.h"

#include <cstdio>
#include <unordered_map>

#include "xacro/internal/attributes.h"
#include "xacro/internal/python_iterators.h"

namespace urdfsnap::xacro {
namespace {

// an instance of a class made by type(): the class it belongs to
struct Instance : Object {
  Value cls;
};

std::string QualifiedName(const TypeObject& t) { return t.module.empty() ? t.name : t.module + "." + t.name; }

Value MakeTypeValue(std::shared_ptr<TypeObject> type, std::function<Value(ValueList&, Kwargs&)> construct) {
  Value v;
  v.type = Value::Type::kType;
  v.fn = std::make_shared<Function>(Function{type->name, std::move(construct), ""});
  v.object = std::move(type);
  return v;
}

const std::unordered_map<std::string, Value>& Registry() {
  static const std::unordered_map<std::string, Value> registry = [] {
    std::unordered_map<std::string, Value> r;
    std::vector<std::shared_ptr<TypeObject>> types;
    for (const TypeConstructor& entry : BuiltinTypeTable()) {
      auto type = std::make_shared<TypeObject>();
      type->name = entry.name;
      type->module = entry.module;
      types.push_back(type);
      const std::string qualified = QualifiedName(*type);
      auto construct = entry.construct;
      r[entry.name] = MakeTypeValue(type, [construct, qualified](ValueList& args, Kwargs& kwargs) {
        if (!construct) throw EvalError("cannot create '" + qualified + "' instances");
        return construct(args, kwargs);
      });
    }
    // bases once every type exists
    for (size_t k = 0; k < types.size(); ++k) {
      const char* base = BuiltinTypeTable()[k].base;
      if (*base) types[k]->base = r.at(base);
    }
    return r;
  }();
  return registry;
}

bool SameType(const Value& a, const Value& b) { return a.object == b.object; }

bool DerivesFrom(const Value& cls, const Value& base) {
  if (SameType(cls, base)) return true;
  const TypeObject& t = TypeOf(cls);
  if (t.is_class) {
    for (const Value& b : t.bases) {
      if (DerivesFrom(b, base)) return true;
    }
    return false;
  }
  return t.base.type == Value::Type::kType && DerivesFrom(t.base, base);
}

// None in a union stands for NoneType
Value UnionMember(const Value& v) { return v.type == Value::Type::kNone ? BuiltinType("NoneType") : v; }

// isinstance/issubclass over a classinfo: true when `test` holds for one of its types
template <class Test>
bool AnyClass(const Value& classinfo, const Test& test, const char* message) {
  switch (classinfo.type) {
    case Value::Type::kType: return test(classinfo);
    case Value::Type::kUnion:
      for (const Value& t : *classinfo.list) {
        if (test(t)) return true;
      }
      return false;
    case Value::Type::kTuple:
      for (const Value& item : *classinfo.list) {
        if (AnyClass(item, test, message)) return true;
      }
      return false;
    default: throw EvalError(message);
  }
}

std::string PointerText(const void* p) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%p", p);
  return buf;
}

// a builtin type's instance made with no arguments, to find its methods on; None when the type
// needs arguments
Value Prototype(const Value& type) {
  static const std::vector<std::string> kNoArguments = {"int", "float", "complex", "bool", "str", "list",
                                                       "tuple", "dict", "set", "frozenset"};
  for (const std::string& name : kNoArguments) {
    if (TypeOf(type).name == name && TypeOf(type).module.empty()) return CallValue(type, {});
  }
  return Value::None();
}

}  // namespace

const TypeObject& TypeOf(const Value& type_value) { return static_cast<const TypeObject&>(*type_value.object); }

Value BuiltinType(const std::string& name) { return Registry().at(name); }

Value TypeOfValue(const Value& v) {
  switch (v.type) {
    case Value::Type::kNone: return BuiltinType("NoneType");
    case Value::Type::kBool: return BuiltinType("bool");
    case Value::Type::kInt: return BuiltinType("int");
    case Value::Type::kFloat: return BuiltinType("float");
    case Value::Type::kComplex: return BuiltinType("complex");
    case Value::Type::kStr: return BuiltinType("str");
    case Value::Type::kList: return BuiltinType(v.wrapped ? "YamlListWrapper" : "list");
    case Value::Type::kTuple: return BuiltinType("tuple");
    case Value::Type::kDict: return BuiltinType(v.wrapped ? "YamlDictWrapper" : "dict");
    case Value::Type::kSet: return BuiltinType("set");
    case Value::Type::kFrozenSet: return BuiltinType("frozenset");
    case Value::Type::kRange: return BuiltinType("range");
    case Value::Type::kSlice: return BuiltinType("slice");
    case Value::Type::kIterator: return BuiltinType(IteratorOf(v).type_name());
    case Value::Type::kType: return BuiltinType("type");
    case Value::Type::kUnion: return BuiltinType("UnionType");
    case Value::Type::kInstance: return static_cast<const Instance&>(*v.object).cls;
    case Value::Type::kFunction: return BuiltinType("builtin_function_or_method");
    case Value::Type::kModule:
    case Value::Type::kScope: return BuiltinType("NameSpace");
    case Value::Type::kBlock: return BuiltinType("Element");
  }
  return BuiltinType("NoneType");
}

std::string TypeRepr(const Value& t) {
  if (t.type == Value::Type::kUnion) {
    std::string out;
    for (const Value& member : *t.list) {
      if (!out.empty()) out += " | ";
      const TypeObject& m = TypeOf(member);
      if (m.name == "NoneType" && m.module.empty()) out += "None";
      else if (m.is_class) out += TypeRepr(member);
      else out += QualifiedName(m);
    }
    return out;
  }
  return "<class '" + QualifiedName(TypeOf(t)) + "'>";
}

bool IsInstance(const Value& v, const Value& classinfo) {
  const Value type = TypeOfValue(v);
  return AnyClass(classinfo, [&](const Value& t) { return DerivesFrom(type, t); },
                  "isinstance() arg 2 must be a type, a tuple of types, or a union");
}

bool IsSubclass(const Value& cls, const Value& classinfo) {
  const auto test = [&](const Value& t) {
    if (cls.type != Value::Type::kType) throw EvalError("issubclass() arg 1 must be a class");
    return DerivesFrom(cls, t);
  };
  if (classinfo.type != Value::Type::kType && classinfo.type != Value::Type::kUnion &&
      classinfo.type != Value::Type::kTuple && cls.type != Value::Type::kType) {
    throw EvalError("issubclass() arg 1 must be a class");
  }
  return AnyClass(classinfo, test, "issubclass() arg 2 must be a class, a tuple of classes, or a union");
}

Value TypeUnion(const Value& a, const Value& b) {
  const auto usable = [](const Value& v) {
    return v.type == Value::Type::kType || v.type == Value::Type::kUnion || v.type == Value::Type::kNone;
  };
  if (!usable(a) || !usable(b)) {
    throw EvalError("unsupported operand type(s) for |: '" + TypeName(a) + "' and '" + TypeName(b) + "'");
  }
  ValueList members;
  for (const Value* side : {&a, &b}) {
    const ValueList parts = side->type == Value::Type::kUnion ? *side->list : ValueList{UnionMember(*side)};
    for (const Value& part : parts) {
      bool seen = false;
      for (const Value& m : members) seen = seen || SameType(m, part);
      if (!seen) members.push_back(part);
    }
  }
  if (members.size() == 1) return members[0];
  Value u = Value::Tuple(std::move(members));
  u.type = Value::Type::kUnion;
  return u;
}

bool UnionEqual(const Value& a, const Value& b) {
  const auto covers = [](const Value& x, const Value& y) {
    for (const Value& t : *x.list) {
      bool found = false;
      for (const Value& s : *y.list) found = found || SameType(t, s);
      if (!found) return false;
    }
    return true;
  };
  return covers(a, b) && covers(b, a);
}

Value MakeClass(const Value& name, const Value& bases, const Value& dict) {
  if (name.type != Value::Type::kStr) {
    throw EvalError("type.__new__() argument 1 must be str, not " + TypeName(name));
  }
  if (bases.type != Value::Type::kTuple) {
    throw EvalError("type.__new__() argument 2 must be tuple, not " + TypeName(bases));
  }
  if (dict.type != Value::Type::kDict) {
    throw EvalError("type.__new__() argument 3 must be dict, not " + TypeName(dict));
  }
  auto type = std::make_shared<TypeObject>();
  type->name = name.s;
  type->is_class = true;
  for (const Value& base : *bases.list) {
    if (base.type != Value::Type::kType) {
      throw EvalError("metaclass conflict: the metaclass of a derived class must be a (non-strict) subclass "
                      "of the metaclasses of all its bases");
    }
    if (!TypeOf(base).is_class) {
      throw EvalError("type(): deriving from the builtin type '" + TypeOf(base).name +
                      "' is not supported by urdfsnap (only from classes made by type())");
    }
    type->bases.push_back(base);
  }
  for (const auto& [key, value] : dict.dict->items) {
    if (key.type == Value::Type::kStr) type->attributes.emplace_back(key.s, value);
  }
  // the constructor hands each instance its class; it holds the class weakly (the class holds it)
  Value cls = MakeTypeValue(type, nullptr);
  cls.fn->call = [class_name = name.s.str(), weak_type = std::weak_ptr<Object>(cls.object),
                  weak_fn = std::weak_ptr<Function>(cls.fn)](ValueList& args, Kwargs& kwargs) {
    if (!args.empty() || !kwargs.empty()) throw EvalError(class_name + "() takes no arguments");
    auto instance = std::make_shared<Instance>();
    instance->cls.type = Value::Type::kType;
    instance->cls.object = weak_type.lock();
    instance->cls.fn = weak_fn.lock();
    Value v;
    v.type = Value::Type::kInstance;
    v.object = std::move(instance);
    return v;
  };
  return cls;
}

Value TypeAttribute(const Value& type, const std::string& name) {
  const TypeObject& t = TypeOf(type);
  if (t.is_class) {
    for (const auto& [key, value] : t.attributes) {
      if (key == name) return value;
    }
    for (const Value& base : t.bases) {
      try {
        return TypeAttribute(base, name);
      } catch (const EvalError&) {
      }
    }
    throw EvalError("type object '" + t.name + "' has no attribute '" + name + "'");
  }
  // a builtin type's method, unbound: python.str.upper('a') is 'a'.upper()
  const Value prototype = Prototype(type);
  bool found = false;
  if (prototype.type != Value::Type::kNone || t.name == "NoneType") {
    try {
      found = GetAttribute(prototype, name).IsCallable();
    } catch (const EvalError&) {
    }
  }
  if (!found) throw EvalError("type object '" + QualifiedName(t) + "' has no attribute '" + name + "'");
  const std::string type_name = t.name;
  Value method = Value::Callable(name, [type, type_name, name](ValueList& args, Kwargs& kwargs) {
    if (args.empty()) throw EvalError("unbound method " + type_name + "." + name + "() needs an argument");
    if (!IsInstance(args[0], type)) {
      throw EvalError("descriptor '" + name + "' for '" + type_name + "' objects doesn't apply to a '" +
                      TypeName(args[0]) + "' object");
    }
    const Value bound = GetAttribute(args[0], name);
    return CallValue(bound, ValueList(args.begin() + 1, args.end()), kwargs);
  });
  method.fn->repr = "<method '" + name + "' of '" + type_name + "' objects>";
  return method;
}

Value InstanceAttribute(const Value& instance, const std::string& name) {
  const Value& cls = static_cast<const Instance&>(*instance.object).cls;
  try {
    return TypeAttribute(cls, name);
  } catch (const EvalError&) {
    throw EvalError("'" + TypeOf(cls).name + "' object has no attribute '" + name + "'");
  }
}

std::string InstanceRepr(const Value& instance) {
  return "<" + TypeName(instance) + " object at " + PointerText(instance.object.get()) + ">";
}

}  // namespace urdfsnap::xacro
