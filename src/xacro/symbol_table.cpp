// Lazy property scopes (xacro's Table).
#include "xacro/internal/symbol_table.h"

#include <algorithm>

#include "xacro/internal/number_format.h"

namespace urdfsnap::xacro {

Value Table::EvalLiteral(Value value) {
  if (value.type != Value::Type::kStr) return value;
  const std::string& s = value.s;
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') return Value::Str(s.substr(1, s.size() - 2));
  // Python 3 accepts underscores in number text (PEP 515); xacro keeps such text as a string
  if (s.find('_') != std::string::npos) return value;
  if (auto i = ParseIntText(s)) return Value::Integer(*i);
  if (auto f = ParseFloatText(s)) return Value::Float(*f);
  if (s == "true" || s == "True") return Value::Bool(true);
  if (s == "false" || s == "False") return Value::Bool(false);
  return value;
}

Value Table::Get(const std::string& key) {
  for (Table* t = this; t; t = t->parent_.get()) {
    auto it = t->entries_.find(key);
    if (it == t->entries_.end()) continue;
    if (!it->second.unevaluated) return it->second.value;
    if (std::find(t->resolving_.begin(), t->resolving_.end(), key) != t->resolving_.end()) {
      std::string chain;
      for (const std::string& k : t->resolving_) chain += k + " -> ";
      throw EvalError("circular variable definition: " + chain + key +
                      "\nConsider disabling lazy evaluation via lazy_eval=\"false\"");
    }
    if (context_->resolving_depth >= kMaxLazyDepth) {
      throw EvalError("maximum recursion depth exceeded while evaluating property '" + key + "'");
    }
    t->resolving_.push_back(key);
    ++context_->resolving_depth;
    const std::string text = it->second.value.s;
    Value result;
    try {
      result = EvalLiteral(context_->evaluator->EvalText(text, t->shared_from_this()));
    } catch (...) {
      t->resolving_.pop_back();
      --context_->resolving_depth;
      throw;
    }
    t->resolving_.pop_back();
    --context_->resolving_depth;
    Entry& entry = t->entries_[key];
    entry.value = result;
    entry.unevaluated = false;
    return result;
  }
  auto g = context_->globals.find(key);
  if (g != context_->globals.end()) return g->second;
  throw EvalError("name '" + key + "' is not defined");
}

bool Table::Contains(const std::string& key) const {
  for (const Table* t = this; t; t = t->parent_.get()) {
    if (t->entries_.count(key)) return true;
  }
  return context_->globals.count(key) != 0;
}

void Table::Set(const std::string& key, Value value, bool lazy) {
  if (context_->globals.count(key) && context_->warnings) {
    context_->warnings->Add("redefining global symbol: " + key);
  }
  value = EvalLiteral(std::move(value));
  Entry& entry = entries_[key];
  entry.unevaluated = lazy && value.type == Value::Type::kStr;
  entry.value = std::move(value);
}

void Table::Remove(const std::string& key) {
  for (Table* t = this; t; t = t->parent_.get()) t->entries_.erase(key);
  if (context_->globals.count(key) && context_->warnings) {
    context_->warnings->Add("Cannot remove global symbol: " + key);
  }
}

Table* Table::Top() {
  Table* t = this;
  while (t->parent_) t = t->parent_.get();
  return t;
}

}  // namespace urdfsnap::xacro
