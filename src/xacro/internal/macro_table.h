// Macro definitions and the scopes that hold them: a macro's parameters (with `:=` defaults, `^`
// and `^|` forwarding, `*`/`**` block parameters), and the tables of macros visible at a point of
// the document (nested per macro expansion, plus the namespaces of includes with ns=).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace urdfsnap::xacro {

struct Node;

// What `name:=^|default` says about one parameter.
struct ParamDefault {
  bool forward = false;                // ^: take the caller's property of the same name
  std::optional<std::string> value;    // the default text, if any
};

struct Macro {
  std::string name;
  const Node* body = nullptr;          // the xacro:macro element
  std::vector<std::string> params;     // in declaration order; block params keep their * or **
  std::map<std::string, ParamDefault> defaults;
  int file = -1;                       // where it was defined
};

// Parses a `params` attribute as xacro does: "a b:=2 c:='x y' d=^|3 *blk **content".
void ParseMacroParams(const std::string& params, Macro& macro);

class MacroTable {
 public:
  struct Entry {
    std::shared_ptr<Macro> macro;
    std::shared_ptr<MacroTable> ns;
  };

  explicit MacroTable(std::shared_ptr<MacroTable> parent = nullptr) : parent_(std::move(parent)) {}

  // The entry named `name` here or in an enclosing table, or nullptr.
  const Entry* Find(const std::string& name) const;
  void SetMacro(const std::string& name, std::shared_ptr<Macro> macro);
  void SetNamespace(const std::string& name, std::shared_ptr<MacroTable> ns);

 private:
  std::shared_ptr<MacroTable> parent_;
  std::unordered_map<std::string, Entry> entries_;
};

}  // namespace urdfsnap::xacro
