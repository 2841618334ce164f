// Bounds on the lists xacro expressions build, so that no expression can exhaust memory or run for
// minutes: one list, tuple, dict or range() holds at most kMaxListItems items (checked before it
// is built), and everything a document's expressions materialise (list items, copies made to
// iterate, comprehension steps) is charged to one budget per document. Real robot descriptions
// use a few thousand items; Python's xacro has no such limits and would run out of memory.
#pragma once

#include <cstddef>

#include "xacro/python_value.h"

namespace urdfsnap::xacro {

// The most items one list, tuple, dict or range() may have (about 150 MB of values).
inline constexpr size_t kMaxListItems = size_t{1} << 20;

// The items all expressions of one document may materialise, comprehension steps included
// (about 600 MB of values if all were alive at once, about a second of work).
inline constexpr size_t kEvaluationBudgetItems = size_t{4} << 20;

// The budget of the expressions evaluated on this thread while it lives. Opening one while
// another is open on the thread does nothing: the outer one (a document's) keeps counting.
class EvaluationBudget {
 public:
  explicit EvaluationBudget(size_t items = kEvaluationBudgetItems);
  ~EvaluationBudget();
  EvaluationBudget(const EvaluationBudget&) = delete;
  EvaluationBudget& operator=(const EvaluationBudget&) = delete;

  // Charges `items` to the open budget; throws EvalError when it is spent. No-op without one.
  static void Charge(size_t items);

 private:
  bool owner_ = false;
};

// Throws EvalError("WHAT too large: N items (the limit is ...)") when n > kMaxListItems; call it
// before building a list of n items.
void CheckListSize(Int n, const char* what);

}  // namespace urdfsnap::xacro
