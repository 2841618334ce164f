// Argument-count and keyword checks worded as CPython words them.
#include "xacro/internal/call_arguments.h"

#include <algorithm>

namespace urdfsnap::xacro {
namespace {

std::string Arguments(size_t n) { return std::to_string(n) + (n == 1 ? " argument" : " arguments"); }

}  // namespace

void TakesOne(const std::string& name, const ValueList& args) {
  if (args.size() != 1) {
    throw EvalError(name + "() takes exactly one argument (" + std::to_string(args.size()) + " given)");
  }
}

void Expected(const std::string& name, const ValueList& args, size_t min, size_t max) {
  const std::string got = ", got " + std::to_string(args.size());
  if (min == max && args.size() != min) throw EvalError(name + " expected " + Arguments(min) + got);
  if (args.size() < min) throw EvalError(name + " expected at least " + Arguments(min) + got);
  if (args.size() > max) throw EvalError(name + " expected at most " + Arguments(max) + got);
}

void TakesAtMost(const std::string& name, const ValueList& args, size_t max) {
  if (args.size() > max) {
    throw EvalError(name + "() takes at most " + Arguments(max) + " (" + std::to_string(args.size()) + " given)");
  }
}

void NoKeywords(const std::string& name, const Kwargs& kwargs) {
  if (!kwargs.empty()) throw EvalError(name + "() takes no keyword arguments");
}

void OnlyKeywords(const std::string& name, const Kwargs& kwargs, const std::vector<std::string>& allowed) {
  for (const auto& [key, value] : kwargs) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw EvalError("'" + key + "' is an invalid keyword argument for " + name + "()");
    }
  }
}

const Value* Keyword(const Kwargs& kwargs, const std::string& key) {
  for (const auto& [k, v] : kwargs) {
    if (k == key) return &v;
  }
  return nullptr;
}

}  // namespace urdfsnap::xacro
