// The in-order xacro processor, a port of xacro's eval_all() and its helpers onto xml_tree.
#include "xacro/internal/processor.h"

#include <glob.h>
#include <pthread.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <regex>

#include "common/error.h"
#include "xacro/internal/expression_evaluator.h"
#include "xacro/internal/builtins.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/number_format.h"
#include "xacro/internal/yaml_loader.h"

namespace urdfsnap::xacro {
namespace {

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

bool IsBlank(const std::string& s) {
  return !s.empty() && s.find_first_not_of(" \t\n\r\f\v") == std::string::npos;
}

bool IsValidName(const std::string& name) {
  static const std::regex kIdentifier("[A-Za-z_][A-Za-z0-9_]*");
  static const char* const kKeywords[] = {"False", "None", "True", "and", "as", "assert", "async", "await",
                                          "break", "class", "continue", "def", "del", "elif", "else",
                                          "except", "finally", "for", "from", "global", "if", "import",
                                          "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise",
                                          "return", "try", "while", "with", "yield"};
  if (!std::regex_match(name, kIdentifier)) return false;
  return std::none_of(std::begin(kKeywords), std::end(kKeywords), [&](const char* k) { return name == k; });
}

// the attribute `key` of a xacro tag, which must be present
const std::string& Required(const Node* node, const std::string& key) {
  const std::string* v = node->Attribute(key);
  if (!v) throw EvalError(node->name + ": missing attribute '" + key + "'");
  return *v;
}

// xacro's get_boolean_value
bool BooleanValue(const Value& value, const std::string& condition) {
  if (value.type == Value::Type::kStr) {
    if (value.s == "true" || value.s == "True") return true;
    if (value.s == "false" || value.s == "False") return false;
    if (auto i = ParseIntText(value.s.str())) return *i != 0;
    throw EvalError("Xacro conditional \"" + condition + "\" evaluated to \"" + value.s +
                    "\", which is not a boolean expression.");
  }
  return Truthy(value);
}

std::string Dirname(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return "";
  return slash == 0 ? "/" : path.substr(0, slash);
}

class TableNames : public NameLookup {
 public:
  explicit TableNames(Table& table) : table_(table) {}
  Value Lookup(const std::string& name) override { return table_.Get(name); }

 private:
  Table& table_;
};

}  // namespace

Processor::Processor(const Options& options, Warnings& warnings)
    : options_(options), warnings_(warnings), pool_(options.max_document_bytes) {
  substitutions_.args = ArgMappings(options.args);
  substitutions_.packages.explicit_dirs = options.packages;
  table_context_.evaluator = this;
  table_context_.warnings = &warnings_;
  table_context_.globals = MakeGlobalSymbols(XacroMembers(), {"load_yaml", "abs_filename", "dotify"},
                                             [this](const std::string& w) { warnings_.Add(w); });
  substitutions_.globals = &table_context_.globals;
  barrier_ = pool_.Allocate(Node::Type::kText);
  barrier_->data = "\n\n";
}

Processor::~Processor() {
  for (const auto& table : namespaces_) table->Clear();
}

std::vector<std::pair<std::string, Value>> Processor::XacroMembers() {
  auto message = [this](const std::string& kind) {
    return Value::Callable(kind, [this, kind](ValueList& a, Kwargs&) {
      std::string text;
      for (const Value& v : a) text += (text.empty() ? "" : " ") + ToStr(v);
      warnings_.Add(Located(kind == "message" ? text : kind + ": " + text));
      return Value::Str("");
    });
  };
  return {
      {"load_yaml", Value::Callable("load_yaml", [this](ValueList& a, Kwargs&) {
         if (a.size() != 1 || a[0].type != Value::Type::kStr) throw EvalError("load_yaml() takes one file name");
         const std::string path = AbsFilename(a[0].s);
         files_.push_back(path);
         file_stack_.push_back({static_cast<int>(files_.size()) - 1, current_ ? current_->line : 0});
         const Symbols globals_only = std::make_shared<Table>(nullptr, &table_context_);
         Value v = LoadYaml(path, [&](const std::string& text) { return EvalExpression(text, globals_only); });
         file_stack_.pop_back();
         dependencies_.push_back(path);
         return v;
       })},
      {"abs_filename", Value::Callable("abs_filename", [this](ValueList& a, Kwargs&) {
         if (a.size() != 1 || a[0].type != Value::Type::kStr) throw EvalError("abs_filename() takes one file name");
         return Value::Str(AbsFilename(a[0].s));
       })},
      {"dotify", Value::Callable("dotify", [](ValueList& a, Kwargs&) {
         if (a.size() != 1 || a[0].type != Value::Type::kDict) throw EvalError("dotify() takes one dict");
         return Wrapped(a[0], true);
       })},
      {"arg", Value::Callable("arg", [this](ValueList& a, Kwargs&) {
         if (a.size() != 1 || a[0].type != Value::Type::kStr) throw EvalError("arg() takes one name");
         auto it = substitutions_.args.find(a[0].s);
         if (it == substitutions_.args.end()) throw EvalError(Repr(a[0]));
         return Value::Str(it->second);
       })},
      {"message", message("message")},
      {"warning", message("warning")},
      {"error", message("error")},
      {"print_location", Value::Callable("print_location", [](ValueList&, Kwargs&) { return Value::Str(""); })},
      {"fatal", Value::Callable("fatal", [](ValueList& a, Kwargs&) -> Value {
         std::string text;
         for (const Value& v : a) text += (text.empty() ? "" : " ") + ToStr(v);
         throw EvalError(text);
       })},
      {"tokenize", Value::Callable("tokenize", [](ValueList& a, Kwargs& kw) {
         if (a.empty() || a[0].type != Value::Type::kStr) throw EvalError("tokenize() takes a string");
         std::string sep = a.size() > 1 ? ToStr(a[1]) : ",; ";
         bool skip_empty = a.size() > 2 ? Truthy(a[2]) : true;
         for (auto& [k, v] : kw) {
           if (k == "sep") sep = ToStr(v);
           else if (k == "skip_empty") skip_empty = Truthy(v);
         }
         EvaluationBudget::ChargeBytes(a[0].s.size());  // the pieces are new text
         ValueList out;
         std::string piece;
         for (char c : a[0].s + sep.substr(0, 1)) {
           if (sep.find(c) == std::string::npos) {
             piece += c;
             continue;
           }
           if (!piece.empty() || !skip_empty) out.push_back(Value::Str(piece));
           piece.clear();
         }
         return Value::List(std::move(out));
       })},
  };
}

std::string Processor::AbsFilename(const std::string& spec) const {
  if (StartsWith(spec, "/")) return spec;
  const std::string base = file_stack_.empty() ? "" : Dirname(files_[file_stack_.back().file]);
  return base.empty() ? spec : base + "/" + spec;
}

std::string Processor::Located(const std::string& message) const {
  std::string out;
  if (current_ && current_->file >= 0) {
    out = SourceLocation{files_[current_->file], current_->line}.ToString() + ": ";
  }
  out += message;
  std::vector<std::string> chain;
  const char* lead = "when instantiating macro: ";
  for (auto it = macro_stack_.rbegin(); it != macro_stack_.rend(); ++it) {
    chain.push_back(lead + (*it)->name + " (" + ((*it)->file >= 0 ? files_[(*it)->file] : "?") + ")");
    lead = "instantiated from: ";
  }
  for (size_t k = file_stack_.size(); k-- > 1;) {
    chain.push_back(files_[file_stack_[k].file] + " included from " +
                    SourceLocation{files_[file_stack_[k - 1].file], file_stack_[k].include_line}.ToString());
  }
  // runaway recursion repeats one line hundreds of times: say it once with a count
  for (size_t k = 0; k < chain.size();) {
    size_t same = k + 1;
    while (same < chain.size() && chain[same] == chain[k]) ++same;
    out += "\n  " + chain[k];
    if (same - k > 2) {
      out += "\n  ... (" + std::to_string(same - k - 1) + " more times)";
      k = same;
    } else {
      ++k;
    }
  }
  return out;
}

void Processor::Fail(const Node* node, const std::string& message) {
  current_ = node;
  throw EvalError(message);
}

Value Processor::EvalExpression(const std::string& text, const Symbols& symbols) {
  auto it = expression_cache_.find(text);
  if (it == expression_cache_.end()) {
    const size_t b = text.find_first_not_of(" \t\n\r\f\v");
    const std::string stripped = b == std::string::npos ? "" : text.substr(b, text.find_last_not_of(" \t\n\r\f\v") - b + 1);
    it = expression_cache_.emplace(text, ParseExpression(stripped)).first;
  }
  TableNames names(*symbols);
  return Evaluate(*it->second, names);
}

Value Processor::EvalText(const std::string& text, const Symbols& symbols) {
  if (text.find('$') == std::string::npos) return Value::Str(text);
  ValueList results;
  const size_t n = text.size();
  size_t pos = 0;
  while (pos < n) {
    if (text[pos] != '$') {
      const size_t next = std::min(text.find('$', pos), n);
      results.push_back(Value::Str(text.substr(pos, next - pos)));
      pos = next;
      continue;
    }
    // $$...{ or $$...( : one $ removed
    size_t run = pos;
    while (run < n && text[run] == '$') ++run;
    if (run - pos >= 2 && run < n && (text[run] == '{' || text[run] == '(')) {
      results.push_back(Value::Str(text.substr(pos + 1, run - pos)));
      pos = run + 1;
      continue;
    }
    if (pos + 1 < n && (text[pos + 1] == '{' || text[pos + 1] == '(')) {
      const char close = text[pos + 1] == '{' ? '}' : ')';
      const size_t end = text.find(close, pos + 2);
      if (end != std::string::npos) {
        const std::string inner = text.substr(pos + 2, end - pos - 2);
        if (close == '}') {
          try {
            const Value expr = EvalText(inner, symbols);
            results.push_back(EvalExpression(ToStr(expr), symbols));
          } catch (const EvalError& e) {
            throw EvalError(std::string(e.what()) + "\n  when evaluating expression '" + inner + "'");
          }
        } else {
          results.push_back(Value::Str(ResolveSubstitution("$(" + ToStr(EvalText(inner, symbols)) + ")", substitutions_)));
        }
        pos = end + 1;
        continue;
      }
    }
    if (pos + 1 == n) {
      results.push_back(Value::Str("$"));
      ++pos;
      continue;
    }
    if (text[pos + 1] != '{' && text[pos + 1] != '(' && text[pos + 1] != '$') {
      size_t end = pos + 1;
      while (end < n && text[end] != '{' && text[end] != '(' && text[end] != '$') ++end;
      results.push_back(Value::Str(text.substr(pos, end - pos)));
      pos = end;
      continue;
    }
    throw EvalError("invalid expression: " + text.substr(pos));
  }
  if (results.size() == 1) return results[0];
  // the size first, so that no text larger than the string limit is built (a property that is
  // the previous one twice, thirty deep, would otherwise take gigabytes)
  std::vector<std::string> texts(results.size());
  size_t size = 0;
  for (size_t k = 0; k < results.size() && size <= kMaxStringBytes; ++k) {
    if (results[k].type != Value::Type::kStr) texts[k] = ToStr(results[k]);
    size += results[k].type == Value::Type::kStr ? results[k].s.size() : texts[k].size();
  }
  CheckStringSize(size, "substituted text");
  std::string joined;
  joined.reserve(size);
  for (size_t k = 0; k < results.size(); ++k) joined += results[k].type == Value::Type::kStr ? results[k].s.str() : texts[k];
  return Value::Str(std::move(joined));
}

void Processor::RemovePreviousComments(Node* node) {
  Node* next = node->next;
  Node* previous = node->prev;
  while (previous) {
    // skip a single whitespace text with at most one newline
    if (previous->type == Node::Type::kText && IsBlank(previous->data) &&
        std::count(previous->data.begin(), previous->data.end(), '\n') <= 1) {
      previous = previous->prev;
    }
    if (previous && previous->type == Node::Type::kComment) {
      Node* comment = previous;
      previous = previous->prev;
      RemoveChild(comment);
    } else {
      // a blank line stops the removal of comments in front of later xacro tags
      if (next && next != barrier_) InsertBefore(node->parent, barrier_, next);
      return;
    }
  }
}

void Processor::Recycle(Node* node) {
  // the comment barrier may sit among the node's children: it lives on
  for (const Node* p = barrier_->parent; p; p = p->parent) {
    if (p == node) {
      RemoveChild(barrier_);
      break;
    }
  }
  pool_.Release(node);
}

void Processor::EvalAll(Node* node, const Macros& macros, const Symbols& symbols) {
  current_ = node;
  for (size_t k = 0; k < node->attributes.size();) {
    auto& [name, value] = node->attributes[k];
    if (StartsWith(name, "xacro:")) {
      node->attributes.erase(node->attributes.begin() + static_cast<long>(k));
      continue;
    }
    if (value.find('$') != std::string::npos) {
      std::string result = ToStr(EvalText(value, symbols));
      pool_.Account(result.size());
      node->attributes[k].second = std::move(result);
    }
    ++k;
  }
  node->RemoveAttribute("xmlns:xacro");

  bool eval_comments = false;
  for (Node* child = node->first; child;) {
    Node* next = child->next;
    current_ = child;
    if (child->type == Node::Type::kElement) {
      eval_comments = false;  // any tag ends comment evaluation
      const std::string& tag = child->name;
      if (tag == "xacro:insert_block") {
        InsertBlock(child, macros, symbols);
      } else if (tag == "xacro:include") {
        ProcessInclude(child, macros, symbols);
      } else if (tag == "xacro:property") {
        GrabProperty(child, symbols);
      } else if (tag == "xacro:macro") {
        GrabMacro(child, macros);
      } else if (tag == "xacro:arg") {
        ProcessArg(child, symbols);
      } else if (tag == "xacro:element") {
        const Value name = EvalText(Required(child, "xacro:name"), symbols);
        if (!Truthy(name)) throw EvalError("xacro:element: empty name");
        child->RemoveAttribute("xacro:name");
        child->name = ToStr(name);
        continue;  // process the element again under its new name
      } else if (tag == "xacro:attribute") {
        const Value name = EvalText(Required(child, "name"), symbols);
        const Value value = EvalText(Required(child, "value"), symbols);
        if (!Truthy(name)) throw EvalError("xacro:attribute: empty name");
        node->SetAttribute(ToStr(name), ToStr(value));
        ReplaceNode(child, nullptr, false);
      } else if (tag == "xacro:if" || tag == "xacro:unless") {
        ProcessCondition(child, macros, symbols);
      } else if (!HandleMacroCall(child, macros, symbols)) {
        EvalAll(child, macros, symbols);
      }
    } else if (child->type == Node::Type::kText) {
      if (child->data.find('$') != std::string::npos) {
        child->data = ToStr(EvalText(child->data, symbols));
        pool_.Account(child->data.size());
      }
      if (!child->data.empty() && !IsBlank(child->data)) eval_comments = false;
    } else if (child->type == Node::Type::kComment) {
      if (child->data.find("xacro:eval-comments") != std::string::npos) {
        eval_comments = child->data.find("xacro:eval-comments:off") == std::string::npos;
        ReplaceNode(child, nullptr, false);
      } else if (eval_comments) {
        child->data = ToStr(EvalText(child->data, symbols));
      }
    }
    child = next;
  }
}

void Processor::InsertBlock(Node* node, const Macros& macros, const Symbols& symbols) {
  const std::string& name = Required(node, "name");
  Value block;
  bool content_only = true;
  if (symbols->Contains("**" + name)) {
    block = symbols->Get("**" + name);
  } else if (symbols->Contains("*" + name)) {
    block = symbols->Get("*" + name);
    content_only = false;
  } else {
    throw EvalError("Undefined block \"" + name + "\"");
  }
  if (block.type != Value::Type::kBlock) throw EvalError("Undefined block \"" + name + "\"");
  Node* copy = pool_.Clone(block.block);
  EvalAll(copy, macros, symbols);
  current_ = node;
  ReplaceNode(node, copy, content_only);
}

void Processor::ProcessInclude(Node* node, const Macros& macros, const Symbols& symbols) {
  const std::string& spec = Required(node, "filename");
  Macros ns_macros = macros;
  Symbols ns_symbols = symbols;
  if (const std::string* ns = node->Attribute("ns"); ns && !ns->empty()) {
    const std::string name = ToStr(EvalText(*ns, symbols));
    ns_macros = std::make_shared<MacroTable>();
    macros->SetNamespace(name, ns_macros);
    ns_symbols = std::make_shared<Table>(symbols, &table_context_, true);
    namespaces_.push_back(ns_symbols);
    symbols->Set(name, Value::Scope(ns_symbols), true);
  }
  const std::string* optional_attr = node->Attribute("optional");
  const bool optional = optional_attr && BooleanValue(Value::Str(*optional_attr), *optional_attr);
  if (node->FirstChildElement()) warnings_.Add(Located("Child elements of a <xacro:include> tag are ignored"));

  const std::string filename = AbsFilename(ToStr(EvalText(spec, symbols)));
  std::vector<std::string> filenames;
  if (filename.find_first_of("*[?") != std::string::npos) {
    glob_t matches{};
    if (glob(filename.c_str(), 0, nullptr, &matches) == 0) {
      for (size_t k = 0; k < matches.gl_pathc; ++k) filenames.push_back(matches.gl_pathv[k]);
    }
    globfree(&matches);
    std::sort(filenames.begin(), filenames.end());
    if (filenames.empty()) warnings_.Add("Include tag's filename spec \"" + filename + "\" matched no files.");
  } else {
    filenames.push_back(filename);
  }

  const int include_line = node->line;
  std::vector<Node*> included;
  for (const std::string& f : filenames) {
    dependencies_.push_back(f);
    if (static_cast<int>(file_stack_.size()) >= options_.max_include_depth) {
      Fail(node, "include depth exceeds the limit of " + std::to_string(options_.max_include_depth) +
                     " (recursive include of " + f + "?)");
    }
    files_.push_back(f);
    const int index = static_cast<int>(files_.size()) - 1;
    Node* document = nullptr;
    try {
      document = ParseXmlFile(f, index, pool_);
    } catch (const IoError& e) {
      if (optional) continue;
      current_ = node;
      // xacro's wording: "No such file or directory: x.xacro [Errno 2] No such file or directory: 'x.xacro'"
      throw EvalError(std::string(e.what()) +
                      (e.errno_value ? " " + PythonOsErrorText(e.errno_value, e.reason, f) : ""));
    }
    file_stack_.push_back({index, include_line});
    Node* root = document->FirstChildElement();
    EvalAll(root, ns_macros, ns_symbols);
    included.push_back(root);
    // lift the included root's namespace declarations to the include's parent
    for (const auto& [key, value] : root->attributes) {
      if (!StartsWith(key, "xmlns:")) continue;
      const std::string* old = node->parent->Attribute(key);
      if (old && *old != value) {
        warnings_.Add("inconsistent namespace redefinitions for " + key + ": old " + *old + ", new " + value + " (" + f + ")");
      } else {
        node->parent->SetAttribute(key, value);
      }
    }
    file_stack_.pop_back();
  }
  current_ = node;
  RemovePreviousComments(node);
  for (Node* root : included) InsertChildrenBefore(root, node);
  RemoveChild(node);
}

void Processor::GrabProperty(Node* node, const Symbols& symbols) {
  RemovePreviousComments(node);
  const std::string name = ToStr(EvalText(Required(node, "name"), symbols));
  if (!IsValidName(name)) throw EvalError("Property names must be valid python identifiers: " + name);
  if (StartsWith(name, "__")) throw EvalError("Property names must not start with double underscore:" + name);
  const std::string* value = node->Attribute("value");
  const std::string* dflt = node->Attribute("default");
  const std::string* remove_attr = node->Attribute("remove");
  const std::string* scope = node->Attribute("scope");
  const std::string* lazy_attr = node->Attribute("lazy_eval");
  const bool remove = BooleanValue(EvalText(remove_attr ? *remove_attr : "false", symbols), remove_attr ? *remove_attr : "");
  if ((value != nullptr) + (dflt != nullptr) + remove > 1) {
    throw EvalError("Property attributes default, value, and remove are mutually exclusive: " + name);
  }
  if (remove && symbols->Contains(name)) {
    symbols->Remove(name);
    RemoveChild(node);
    return;
  }
  if (dflt) {
    if (scope) warnings_.Add(Located(name + ": default property value can only be defined on local scope"));
    if (symbols->Contains(name)) {
      RemoveChild(node);
      return;
    }
    value = dflt;
  }
  std::string key = name;
  Value stored;
  if (value) {
    stored = Value::Str(*value);
  } else {
    key = "**" + name;
    stored = Value::Block(node);
  }
  RemoveChild(node);
  bool lazy = BooleanValue(EvalText(lazy_attr ? *lazy_attr : "true", symbols), lazy_attr ? *lazy_attr : "");
  Table* target = symbols.get();
  if (scope && *scope == "global") {
    target = symbols->Top();
    lazy = false;
  } else if (scope && *scope == "parent") {
    if (!symbols->parent()) {
      // the reference fails here too (it tries to store into its dict of global symbols)
      throw EvalError(name + ": no parent scope at global scope");
    }
    target = symbols->parent().get();
    lazy = false;
    if (!symbols->is_namespace()) {
      // in a macro scope: skip the namespaces to reach the caller's scope
      while (target->is_namespace() && target->parent()) target = target->parent().get();
    }
  }
  if (!lazy && stored.type == Value::Type::kStr) stored = EvalText(stored.s, symbols);
  target->Set(key, std::move(stored), lazy);
}

void Processor::GrabMacro(Node* node, const Macros& macros) {
  RemovePreviousComments(node);
  std::string name = Required(node, "name");
  if (name == "call") throw EvalError("Invalid use of macro name 'call'");
  if (name.find('.') != std::string::npos) {
    throw EvalError("macro names must not contain '.' (reserved for namespaces): " + name);
  }
  if (StartsWith(name, "xacro:")) {
    warnings_.Add(Located("macro names must not contain prefix 'xacro:': " + name));
    name = name.substr(6);
  }
  auto macro = std::make_shared<Macro>();
  macro->name = name;
  macro->body = node;
  macro->file = node->file;
  if (const std::string* params = node->Attribute("params")) ParseMacroParams(*params, *macro);
  macros->SetMacro(name, std::move(macro));
  RemoveChild(node);
}

void Processor::ProcessArg(Node* node, const Symbols& symbols) {
  const std::string& name = Required(node, "name");
  const std::string& dflt = Required(node, "default");
  if (!substitutions_.args.count(name)) substitutions_.args[name] = ToStr(EvalText(dflt, symbols));
  RemovePreviousComments(node);
  RemoveChild(node);
}

void Processor::ProcessCondition(Node* node, const Macros& macros, const Symbols& symbols) {
  RemovePreviousComments(node);
  const std::string& condition = Required(node, "value");
  bool keep = BooleanValue(EvalText(condition, symbols), condition);
  if (node->name == "xacro:unless") keep = !keep;
  if (keep) {
    EvalAll(node, macros, symbols);
    ReplaceNode(node, node, true);
  } else {
    RemoveChild(node);
  }
}

bool Processor::HandleMacroCall(Node* node, const Macros& macros, const Symbols& symbols) {
  if (node->name == "xacro:call") {
    const Value name = EvalText(Required(node, "macro"), symbols);
    node->RemoveAttribute("macro");
    node->name = "xacro:" + ToStr(name);
    ExpandMacro(node, ToStr(name), macros, symbols);
    return true;
  }
  if (StartsWith(node->name, "xacro:")) {
    ExpandMacro(node, node->name.substr(6), macros, symbols);
    return true;
  }
  // ROS Melodic's legacy call: a tag that names a macro defined at this point, unless that macro
  // is being expanded (macro bodies often hold an element named like the macro: <link> in "link")
  if (options_.xacro_ns) return false;
  const MacroTable::Entry* entry = macros->Find(node->name);
  if (!entry || !entry->macro) return false;
  for (const auto& active : macro_stack_) {
    if (active->name == node->name) return false;
  }
  // one warning per macro, made at the end (a tutorial robot calls each macro several times)
  auto calls = std::find_if(legacy_calls_.begin(), legacy_calls_.end(),
                            [&](const LegacyCalls& c) { return c.name == node->name; });
  if (calls == legacy_calls_.end()) {
    legacy_calls_.push_back({node->name, SourceLocation{node->file >= 0 ? files_[node->file] : "", node->line}.ToString(), 0});
    calls = legacy_calls_.end() - 1;
  }
  ++calls->count;
  ExpandMacro(node, node->name, macros, symbols);
  return true;
}

void Processor::ReportLegacyCalls() {
  for (const LegacyCalls& c : legacy_calls_) {
    const std::string calls = c.count == 1 ? "" : " (" + std::to_string(c.count) + " calls, the first here)";
    warnings_.Add(c.first_location + ": <" + c.name + "> is a legacy macro call without the xacro: prefix" + calls +
                  ", expanded as ROS Melodic's xacro did; write <xacro:" + c.name +
                  "> instead, or pass --xacro-ns to leave such tags alone");
  }
  legacy_calls_.clear();
}

Processor::MacroInScope Processor::FindMacro(const Node* node, const std::string& name, const Macros& macros,
                                             const Symbols& symbols) {
  // resolve the name, then (namespace.)*name with the namespace's macros and properties
  Macros scope_macros = macros;
  Symbols scope_symbols = symbols;
  const MacroTable::Entry* entry = macros->Find(name);
  if (!entry || !entry->macro) {
    entry = nullptr;
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t dot = name.find('.'); dot != std::string::npos; dot = name.find('.', start)) {
      parts.push_back(name.substr(start, dot - start));
      start = dot + 1;
    }
    if (!parts.empty()) {
      bool ok = true;
      for (const std::string& ns : parts) {
        const MacroTable::Entry* e = scope_macros->Find(ns);
        if (!e || !e->ns || !scope_symbols->Contains(ns)) {
          ok = false;
          break;
        }
        const Value table = scope_symbols->Get(ns);
        if (table.type != Value::Type::kScope) {
          ok = false;
          break;
        }
        scope_macros = e->ns;
        scope_symbols = table.scope;
      }
      if (ok) entry = scope_macros->Find(name.substr(start));
      if (entry && !entry->macro) entry = nullptr;
    }
  }
  if (!entry) throw EvalError("unknown macro name: " + node->name);
  return {entry->macro, scope_macros, scope_symbols};
}

void Processor::BindMacroArguments(Node* node, const MacroInScope& scope, Table& local_symbols) {
  const Macro& macro = *scope.macro;
  std::vector<std::string> params = macro.params;
  for (auto& [key, value] : node->attributes) {
    auto it = std::find(params.begin(), params.end(), key);
    if (it == params.end()) Fail(node, "Invalid parameter \"" + key + "\"");
    params.erase(it);
    local_symbols.Set(key, EvalText(value, scope.symbols), false);
    value.clear();  // not evaluated again below
  }
  EvalAll(node, scope.macros, scope.symbols);  // the blocks, in the caller's scope

  const Node* block = node->FirstChildElement();
  for (auto it = params.begin(); it != params.end();) {
    if ((*it)[0] != '*') {
      ++it;
      continue;
    }
    if (!block) Fail(node, "Not enough blocks");
    local_symbols.Set(*it, Value::Block(block), true);
    block = block->NextSiblingElement();
    it = params.erase(it);
  }
  if (block) Fail(node, "Unused block \"" + block->name + "\"");

  for (auto it = params.begin(); it != params.end();) {
    auto d = macro.defaults.find(*it);
    if ((*it)[0] == '*' || d == macro.defaults.end() || (!d->second.forward && !d->second.value)) {
      ++it;
      continue;
    }
    current_ = node;
    Value value;
    if (d->second.forward && scope.symbols->Contains(*it)) {
      value = scope.symbols->Get(*it);
    } else if (d->second.value) {
      value = EvalText(*d->second.value, scope.symbols);
    } else {
      Fail(node, "Undefined property to forward: " + *it);
    }
    local_symbols.Set(*it, std::move(value), false);
    it = params.erase(it);
  }
  if (!params.empty()) {
    std::string list;
    for (const std::string& p : params) list += (list.empty() ? "" : ",") + p;
    Fail(node, "Undefined parameters [" + list + "]");
  }
}

void Processor::ExpandMacro(Node* node, const std::string& name, const Macros& macros, const Symbols& symbols) {
  const MacroInScope scope = FindMacro(node, name, macros, symbols);
  const std::shared_ptr<Macro> macro = scope.macro;  // keep it alive if redefined in its body
  if (static_cast<int>(macro_stack_.size()) >= options_.max_macro_depth) {
    throw EvalError("maximum macro recursion depth (" + std::to_string(options_.max_macro_depth) +
                    ") exceeded in macro '" + macro->name + "'");
  }
  macro_stack_.push_back(macro);

  Node* body = pool_.Clone(macro->body);
  auto local_symbols = std::make_shared<Table>(scope.symbols, &table_context_);
  auto local_macros = std::make_shared<MacroTable>(scope.macros);
  BindMacroArguments(node, scope, *local_symbols);

  EvalAll(body, local_macros, local_symbols);
  current_ = node;
  RemovePreviousComments(node);
  for (const auto& [key, value] : body->attributes) {
    if (StartsWith(key, "xmlns:")) node->parent->SetAttribute(key, value);
  }
  ReplaceNode(node, body, true);
  macro_stack_.pop_back();
  // the call (with its blocks) and the emptied body copy are no longer referenced
  Recycle(body);
  Recycle(node);
}

Result Processor::Run(const std::string& path) {
  const EvaluationBudget budget;  // one for all of the document's expressions
  // the legacy-call warnings, whether the expansion succeeds or fails
  struct ReportAtExit {
    Processor& processor;
    ~ReportAtExit() { processor.ReportLegacyCalls(); }
  } report{*this};
  try {
    files_.push_back(path);
    file_stack_.push_back({0, 0});
    Node* document = nullptr;
    try {
      document = ParseXmlFile(path, 0, pool_);
    } catch (const IoError& e) {
      throw Error(e.what());
    }
    substitutions_.packages.near_file = path;
    Node* root = document->FirstChildElement();
    if (const std::string* target = root->Attribute("xacro:targetNamespace")) {
      const std::string ns = *target;
      root->RemoveAttribute("xacro:targetNamespace");
      root->SetAttribute("xmlns", ns);
    }
    EvalAll(root, std::make_shared<MacroTable>(), std::make_shared<Table>(nullptr, &table_context_));

    // xacro's banner, before everything else in the document
    char line[256];
    const std::string rule = " " + std::string(83, '=') + " ";
    std::snprintf(line, sizeof line, " |    This document was autogenerated by xacro from %-30s | ", path.c_str());
    const std::string from = line;
    std::snprintf(line, sizeof line, " |    EDITING THIS FILE BY HAND IS NOT RECOMMENDED  %-30s | ", "");
    Node* first = document->first;
    for (const std::string& text : {rule, from, std::string(line), rule}) {
      Node* comment = pool_.Allocate(Node::Type::kComment);
      comment->data = text;
      InsertBefore(document, comment, first);
    }
    Result result;
    result.xml = WriteXml(document);
    for (const std::string& d : dependencies_) {
      if (std::find(result.dependencies.begin(), result.dependencies.end(), d) == result.dependencies.end()) {
        result.dependencies.push_back(d);
      }
    }
    return result;
  } catch (const EvalError& e) {
    throw Error(Located(e.what()));
  } catch (const DocumentSizeError& e) {
    throw Error(Located(e.what()));
  } catch (const Error& e) {
    // already located (XML syntax, element depth): add the macro and include chain
    const Node* saved = current_;
    current_ = nullptr;
    std::string message = Located(e.what());
    current_ = saved;
    throw Error(message);
  }
}

std::map<std::string, std::string> ArgMappings(const std::vector<std::pair<std::string, std::string>>& args) {
  std::map<std::string, std::string> mappings;
  for (const auto& [name, value] : args) {
    if (value.empty()) continue;
    if (name.size() >= 2 && name[0] == '_' && name[1] != '_') continue;
    mappings[name] = value;
  }
  return mappings;
}

Result ExpandFile(const std::string& path, const Options& options, Warnings& warnings) {
  // Nested macros, blocks and includes recurse deeply before the limits stop them: run on a thread
  // whose stack is large enough for any depth the limits allow (only touched pages are used).
  constexpr size_t kStackBytes = size_t{256} << 20;
  struct Job {
    const std::string& path;
    const Options& options;
    Warnings& warnings;
    Result result;
    std::exception_ptr error;
  } job{path, options, warnings, {}, nullptr};
  auto body = [](void* arg) -> void* {
    auto* j = static_cast<Job*>(arg);
    try {
      Processor processor(j->options, j->warnings);
      j->result = processor.Run(j->path);
    } catch (...) {
      j->error = std::current_exception();
    }
    return nullptr;
  };
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, kStackBytes);
  pthread_t thread;
  const bool started = pthread_create(&thread, &attr, body, &job) == 0;
  pthread_attr_destroy(&attr);
  if (started) {
    pthread_join(thread, nullptr);
  } else {
    body(&job);
  }
  if (job.error) std::rethrow_exception(job.error);
  return std::move(job.result);
}

}  // namespace urdfsnap::xacro
