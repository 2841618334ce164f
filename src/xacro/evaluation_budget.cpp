// EvaluationBudget: one counter per thread, owned by the outermost open budget.
#include "xacro/evaluation_budget.h"

#include <string>


namespace urdfsnap::xacro {

namespace {

struct Counter {
  bool open = false;
  size_t left = 0;
  size_t total = 0;
};

thread_local Counter counter;

}  // namespace

EvaluationBudget::EvaluationBudget(size_t items) {
  if (counter.open) return;
  counter = {true, items, items};
  owner_ = true;
}

EvaluationBudget::~EvaluationBudget() {
  if (owner_) counter = {};
}

void EvaluationBudget::Charge(size_t items) {
  if (!counter.open) return;
  if (items > counter.left) {
    counter.left = 0;
    throw EvalError("expressions build more than " + std::to_string(counter.total) +
                    " list items in all (runaway comprehension or range()?)");
  }
  counter.left -= items;
}

void CheckListSize(Int n, const char* what) {
  if (n > Int(kMaxListItems)) {
    throw EvalError(std::string(what) + " too large: " + ToStr(Value::Integer(n)) +
                    " items (the limit is " + std::to_string(kMaxListItems) + ")");
  }
  EvaluationBudget::Charge(static_cast<size_t>(n));
}

}  // namespace urdfsnap::xacro
