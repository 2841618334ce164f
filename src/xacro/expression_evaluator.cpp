// Tree-walking evaluation of Python expressions.
#include "xacro/internal/expression_evaluator.h"

#include <optional>
#include <utility>
#include <vector>

#include "xacro/internal/attributes.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/operators.h"
#include "xacro/internal/python_hash.h"
#include "xacro/internal/python_set.h"

namespace urdfsnap::xacro {
namespace {

class Evaluator {
 public:
  explicit Evaluator(NameLookup& names) : names_(names) {}

  Value Eval(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::kConst: return e.constant;
      case Expr::Kind::kName: {
        for (auto it = locals_.rbegin(); it != locals_.rend(); ++it) {
          if (it->first == e.name) return it->second;
        }
        return names_.Lookup(e.name);
      }
      case Expr::Kind::kAttr: return GetAttribute(Eval(*e.kids[0]), e.name);
      case Expr::Kind::kSubscript: {
        const Value v = Eval(*e.kids[0]);
        const Expr& index = *e.kids[1];
        if (index.kind != Expr::Kind::kSlice) return Subscript(v, Eval(index));
        // v[a:b:c] is v[slice(a, b, c)]
        auto bound = [this](const ExprPtr& b) { return b ? Eval(*b) : Value::None(); };
        Value start = bound(index.kids[0]), stop = bound(index.kids[1]);
        return Subscript(v, Value::SliceOf(std::move(start), std::move(stop), bound(index.kids[2])));
      }
      case Expr::Kind::kSlice: throw EvalError("invalid syntax (<expression>, line 1)");
      case Expr::Kind::kCall: return Call(e);
      case Expr::Kind::kUnary: {
        const Value v = Eval(*e.kids[0]);
        if (e.name == "not") return Value::Bool(!Truthy(v));
        return UnaryOp(e.name, v);
      }
      case Expr::Kind::kBinary: {
        const Value a = Eval(*e.kids[0]);
        return BinaryOp(e.name, a, Eval(*e.kids[1]));
      }
      case Expr::Kind::kAnd:
      case Expr::Kind::kOr: {
        // Python returns the deciding operand itself
        Value v;
        for (const auto& kid : e.kids) {
          v = Eval(*kid);
          if (Truthy(v) == (e.kind == Expr::Kind::kOr)) return v;
        }
        return v;
      }
      case Expr::Kind::kCompare: {
        Value left = Eval(*e.kids[0]);
        for (size_t k = 0; k < e.ops.size(); ++k) {
          Value right = Eval(*e.kids[k + 1]);
          if (!CompareOp(e.ops[k], left, right)) return Value::Bool(false);
          left = std::move(right);
        }
        return Value::Bool(true);
      }
      case Expr::Kind::kIfElse:
        return Truthy(Eval(*e.kids[1])) ? Eval(*e.kids[0]) : Eval(*e.kids[2]);
      case Expr::Kind::kList:
      case Expr::Kind::kTuple: {
        ValueList items;
        items.reserve(e.kids.size());
        for (const auto& kid : e.kids) items.push_back(Eval(*kid));
        return e.kind == Expr::Kind::kList ? Value::List(std::move(items)) : Value::Tuple(std::move(items));
      }
      case Expr::Kind::kDict: {
        DictBuilder items;
        for (size_t k = 0; k + 1 < e.kids.size(); k += 2) {
          Value key = Eval(*e.kids[k]);
          items.Put(std::move(key), Eval(*e.kids[k + 1]));
        }
        return Value::Dict(items.Take());
      }
      case Expr::Kind::kSet: {
        Value set = MakeSet(Value::Type::kSet);
        for (const auto& kid : e.kids) SetOf(set).Add(Eval(*kid));
        return set;
      }
      case Expr::Kind::kListComp:
      case Expr::Kind::kSetComp: {
        ValueList out;
        Comprehend(e, 0, out);
        if (e.kind == Expr::Kind::kListComp) return Value::List(std::move(out));
        Value set = MakeSet(Value::Type::kSet);
        for (const Value& v : out) SetOf(set).Add(v);
        return set;
      }
    }
    throw EvalError("invalid syntax (<expression>, line 1)");
  }

 private:
  bool CompareOp(const std::string& op, const Value& a, const Value& b) {
    if (op == "==") return Equal(a, b);
    if (op == "!=") return !Equal(a, b);
    if (op == "in") return Contains(b, a);
    if (op == "not in") return !Contains(b, a);
    if (op == "is" || op == "is not") {
      // identity: None, bools and the same container, type or object are the cases that matter
      bool same = a.type == b.type && (a.type == Value::Type::kNone ||
                                       (a.type == Value::Type::kBool && a.b == b.b) ||
                                       (a.list && a.list == b.list) || (a.dict && a.dict == b.dict) ||
                                       (a.object && a.object == b.object) || (a.fn && a.fn == b.fn));
      return op == "is" ? same : !same;
    }
    return RichCompare(op, a, b);
  }

  Value Call(const Expr& e) {
    const Value callee = Eval(*e.kids[0]);
    const size_t n_kw = e.ops.size();
    const size_t n_pos = e.kids.size() - 1 - n_kw;
    ValueList args;
    args.reserve(n_pos);
    for (size_t k = 0; k < n_pos; ++k) args.push_back(Eval(*e.kids[1 + k]));
    Kwargs kwargs;
    for (size_t k = 0; k < n_kw; ++k) kwargs.emplace_back(e.ops[k], Eval(*e.kids[1 + n_pos + k]));
    return CallValue(callee, std::move(args), std::move(kwargs));
  }

  void Comprehend(const Expr& e, size_t clause_index, ValueList& out) {
    if (clause_index == e.clauses.size()) {
      if (out.size() == kMaxListItems) CheckListSize(static_cast<Int>(out.size() + 1), "comprehension result");
      EvaluationBudget::Charge(1);
      out.push_back(Eval(*e.kids[0]));
      return;
    }
    const ComprehensionClause& clause = e.clauses[clause_index];
    const NextFunction next = IterateLazily(Eval(*clause.iter));
    const size_t mark = locals_.size();
    while (const std::optional<Value> item = next()) {
      EvaluationBudget::Charge(1);  // filtered-out steps are work too
      locals_.resize(mark);
      if (clause.unpack) {
        const ValueList parts = Iterate(*item);
        if (parts.size() != clause.targets.size()) {
          throw EvalError("cannot unpack " + std::to_string(parts.size()) + " values into " +
                          std::to_string(clause.targets.size()) + " names");
        }
        for (size_t k = 0; k < parts.size(); ++k) locals_.emplace_back(clause.targets[k], parts[k]);
      } else {
        locals_.emplace_back(clause.targets[0], *item);
      }
      bool keep = true;
      for (const auto& cond : clause.conditions) {
        if (!Truthy(Eval(*cond))) {
          keep = false;
          break;
        }
      }
      if (keep) Comprehend(e, clause_index + 1, out);
    }
    locals_.resize(mark);
  }

  NameLookup& names_;
  std::vector<std::pair<std::string, Value>> locals_;  // comprehension variables, innermost last
};

}  // namespace

Value Evaluate(const Expr& expr, NameLookup& names) {
  const EvaluationBudget budget;  // the document's, when a processor has opened one
  return Evaluator(names).Eval(expr);
}

}  // namespace urdfsnap::xacro
