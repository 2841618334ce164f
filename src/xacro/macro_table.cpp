// Macro parameter parsing (xacro's re_macro_arg) and macro scopes.
#include "xacro/internal/macro_table.h"

#include <regex>

namespace urdfsnap::xacro {

void ParseMacroParams(const std::string& params, Macro& macro) {
  // param, then := or =, optional ^ or ^|, a default (${...}, $(...), quoted or bare words), rest.
  // The repeated group of quoted and bare words matches each character in one way only: a quote
  // runs to its first closing quote and a bare word is taken a character at a time. Written as
  // xacro's `'.*?'|".*?"|[^\s'"]+`, a default the rest could not follow was split every possible
  // way (a fuzzed macro of 120 letters had not finished after 10 minutes); the two differ only
  // where a quote is left open, which neither reads as a default.
  static const std::regex kArg(
      "^\\s*([^\\s:=]+?)\\s*:?=\\s*(\\^\\|?)?(\\$\\{.*?\\}|\\$\\(.*?\\)|"
      "(?:'[^'\\r\\n]*'|\"[^\"\\r\\n]*\"|[^\\s'\"])+|)(?:\\s+|$)(.*)");
  std::string rest = params;
  macro.params.clear();
  macro.defaults.clear();
  while (rest.find_first_not_of(" \t\n\r\f\v") != std::string::npos) {
    std::smatch m;
    if (std::regex_search(rest, m, kArg)) {
      const std::string name = m[1];
      ParamDefault d;
      d.forward = m[2].matched && m[2].length() > 0;
      if (m[3].length() > 0) d.value = m[3].str();
      macro.params.push_back(name);
      macro.defaults[name] = d;
      rest = m[4];
    } else {
      const size_t b = rest.find_first_not_of(" \t\n\r\f\v");
      const size_t e = rest.find_first_of(" \t\n\r\f\v", b);
      macro.params.push_back(rest.substr(b, e == std::string::npos ? std::string::npos : e - b));
      rest = e == std::string::npos ? "" : rest.substr(e);
    }
  }
}

const MacroTable::Entry* MacroTable::Find(const std::string& name) const {
  for (const MacroTable* t = this; t; t = t->parent_.get()) {
    auto it = t->entries_.find(name);
    if (it != t->entries_.end()) return &it->second;
  }
  return nullptr;
}

void MacroTable::SetMacro(const std::string& name, std::shared_ptr<Macro> macro) {
  entries_[name] = Entry{std::move(macro), nullptr};
}

void MacroTable::SetNamespace(const std::string& name, std::shared_ptr<MacroTable> ns) {
  entries_[name] = Entry{nullptr, std::move(ns)};
}

}  // namespace urdfsnap::xacro
