// xacro's property scopes: a chain of tables from a macro's local scope up to the document's top
// level and finally the global symbols (builtins, math, xacro helpers). Properties are stored as
// given and evaluated lazily at first read, in the scope of their definition, then cached.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/warnings.h"
#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

class Table;

// Evaluates property text (`${}`, `$()` and plain text) in a scope; the processor implements it.
class TextEvaluator {
 public:
  virtual ~TextEvaluator() = default;
  virtual Value EvalText(const std::string& text, const std::shared_ptr<Table>& scope) = 0;
};

// What every table of one run shares.
struct TableContext {
  std::unordered_map<std::string, Value> globals;  // the root: builtins, math, python, xacro
  TextEvaluator* evaluator = nullptr;
  Warnings* warnings = nullptr;
  int resolving_depth = 0;  // lazy properties being evaluated, nested
};

// Lazy properties may refer to lazy properties; chains deeper than this end with an error (as
// Python's recursion limit ends them in xacro) instead of exhausting the stack.
inline constexpr int kMaxLazyDepth = 1000;

class Table : public std::enable_shared_from_this<Table> {
 public:
  // A scope below `parent` (nullptr: the top level, right below the globals). A namespace table
  // is the property scope of an include with ns=.
  Table(std::shared_ptr<Table> parent, TableContext* context, bool is_namespace = false)
      : parent_(std::move(parent)), context_(context), is_namespace_(is_namespace) {}

  // Python's value of `key`: this table, its ancestors, then the globals; a lazy property is
  // evaluated here on first read. Throws EvalError "name 'key' is not defined" when absent and
  // "circular variable definition: a -> b -> a ..." for a property defined through itself.
  Value Get(const std::string& key);

  // Whether `key` is visible from this table (globals included).
  bool Contains(const std::string& key) const;

  // Defines `key` here. A text value is retyped as xacro does (int, float, bool, quotes stripped)
  // and, when `lazy`, kept unevaluated until first read. Warns when shadowing a global symbol.
  void Set(const std::string& key, Value value, bool lazy);

  // Removes `key` from this table and its ancestors (not from the globals).
  void Remove(const std::string& key);

  const std::shared_ptr<Table>& parent() const { return parent_; }
  bool is_namespace() const { return is_namespace_; }
  TableContext* context() const { return context_; }
  // Drops every property and the link to the parent: a namespace table stored in its parent
  // forms a reference cycle that the end of a run breaks this way.
  void Clear() {
    entries_.clear();
    parent_.reset();
  }

  // The top-level table (whose parent is the globals).
  Table* Top();

  // xacro's literal typing of a text value: 'quoted' -> quoted, "1.50" -> 1.5, "007" -> 7,
  // "true" -> True; text containing '_' and other text stays as it is.
  static Value EvalLiteral(Value value);

 private:
  struct Entry {
    Value value;
    bool unevaluated = false;
  };
  std::shared_ptr<Table> parent_;
  TableContext* context_;
  bool is_namespace_;
  std::unordered_map<std::string, Entry> entries_;
  std::vector<std::string> resolving_;  // properties being evaluated (to detect cycles)
};

}  // namespace urdfsnap::xacro
