// The in-order xacro processor: walks the document once, editing it in place as xacro's
// eval_all() does (properties, macros, includes, conditionals, blocks, args, dynamic elements and
// attributes, comment handling), with limits on include depth, macro depth and document size.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/warnings.h"
#include "xacro/internal/expression_parser.h"
#include "xacro/internal/macro_table.h"
#include "xacro/internal/substitution_args.h"
#include "xacro/internal/symbol_table.h"
#include "xacro/xacro.h"
#include "xacro/internal/xml_tree.h"

namespace urdfsnap::xacro {

class Processor : public TextEvaluator {
 public:
  Processor(const Options& options, Warnings& warnings);
  ~Processor() override;
  Processor(const Processor&) = delete;
  Processor& operator=(const Processor&) = delete;

  // Expands the file; throws urdfsnap::Error with location and include/macro chain.
  Result Run(const std::string& path);

  // xacro's eval_text: `${expr}` and `$(subst)` pieces evaluated, `$$` escapes undone, other
  // text kept; a lone piece keeps its Python type, several are joined as text.
  Value EvalText(const std::string& text, const std::shared_ptr<Table>& scope) override;

 private:
  using Macros = std::shared_ptr<MacroTable>;
  using Symbols = std::shared_ptr<Table>;

  // one entry of the file stack: the file and the line of the include that opened it
  struct OpenFile {
    int file;
    int include_line;
  };

  void EvalAll(Node* node, const Macros& macros, const Symbols& symbols);
  void InsertBlock(Node* node, const Macros& macros, const Symbols& symbols);
  void ProcessInclude(Node* node, const Macros& macros, const Symbols& symbols);
  void GrabProperty(Node* node, const Symbols& symbols);
  void GrabMacro(Node* node, const Macros& macros);
  void ProcessArg(Node* node, const Symbols& symbols);
  void ProcessCondition(Node* node, const Macros& macros, const Symbols& symbols);
  bool HandleMacroCall(Node* node, const Macros& macros, const Symbols& symbols);
  // A macro call's steps: the macro a name means in the caller's scope (with the namespace's
  // macros and properties for ns.name), its parameters bound from the call's attributes, blocks
  // and defaults, then its body expanded in place of the call.
  struct MacroInScope {
    std::shared_ptr<Macro> macro;
    Macros macros;
    Symbols symbols;
  };
  MacroInScope FindMacro(const Node* node, const std::string& name, const Macros& macros, const Symbols& symbols);
  void BindMacroArguments(Node* node, const MacroInScope& scope, Table& local_symbols);
  void ExpandMacro(Node* node, const std::string& name, const Macros& macros, const Symbols& symbols);
  void RemovePreviousComments(Node* node);
  // Gives a node that left the document (and its subtree) back to the pool.
  void Recycle(Node* node);
  // Adds one warning per macro called the legacy way (without xacro:), with the number of calls
  // and the first one's location.
  void ReportLegacyCalls();

  Value EvalExpression(const std::string& text, const Symbols& symbols);
  std::string AbsFilename(const std::string& spec) const;
  std::vector<std::pair<std::string, Value>> XacroMembers();
  [[noreturn]] void Fail(const Node* node, const std::string& message);
  std::string Located(const std::string& message) const;

  const Options& options_;
  Warnings& warnings_;
  NodePool pool_;
  TableContext table_context_;
  SubstitutionContext substitutions_;
  std::vector<std::string> files_;
  std::vector<OpenFile> file_stack_;
  std::vector<std::shared_ptr<const Macro>> macro_stack_;  // kept alive for error messages
  std::vector<std::string> dependencies_;
  std::vector<std::shared_ptr<Table>> namespaces_;  // include ns= tables, cleared at the end
  std::unordered_map<std::string, ExprPtr> expression_cache_;
  // legacy macro calls, per macro in the order of their first call: its location and the count
  struct LegacyCalls {
    std::string name;
    std::string first_location;
    int count = 0;
  };
  std::vector<LegacyCalls> legacy_calls_;
  const Node* current_ = nullptr;  // the node being processed, for error locations
  Node* barrier_ = nullptr;        // xacro's _empty_text_node: stops comment removal
};

}  // namespace urdfsnap::xacro
