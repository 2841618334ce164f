// Fuzz target: xacro's Python expression parser and evaluator (what `${...}` holds), with xacro's
// global names and a few properties, and the result's text. Only EvalError may come out.
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "fuzz_evaluation_budget.h"
#include "xacro/internal/builtins.h"
#include "xacro/internal/expression_evaluator.h"
#include "xacro/internal/expression_parser.h"

namespace {

using namespace urdfsnap::xacro;

class Names : public NameLookup {
 public:
  Names() : globals_(MakeGlobalSymbols({}, {}, [](const std::string&) {})) {
    globals_["x"] = Value::Integer(3);
    globals_["s"] = Value::Str("link");
    globals_["xyz"] = Value::List({Value::Float(0.1), Value::Float(-2), Value::Integer(7)});
  }
  Value Lookup(const std::string& name) override {
    if (auto it = globals_.find(name); it != globals_.end()) return it->second;
    throw EvalError("name '" + name + "' is not defined");
  }

 private:
  std::unordered_map<std::string, Value> globals_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static Names names;
  const auto budget = urdfsnap::fuzz::SmallEvaluationBudget();
  try {
    const ExprPtr expr = ParseExpression(std::string(reinterpret_cast<const char*>(data), size));
    ToStr(Evaluate(*expr, names));
  } catch (const EvalError&) {
  }
  return 0;
}
