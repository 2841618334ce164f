// For the fuzz targets that evaluate xacro expressions: the evaluator's document budgets scaled
// down, so that the same limit code ends a runaway input in a fraction of a second under the
// sanitizers. At full size an input that spends a budget takes up to 8.5 s there (measured: a
// million split() lists), so one spending all three could near libFuzzer's 30 s timeout, and a
// 10 s CI run spent 36 s, mostly on a few such seeds. The full budgets are unit-tested
// (tests/xacro/).
#pragma once

#include "xacro/internal/evaluation_budget.h"

namespace urdfsnap::fuzz {

inline constexpr size_t kEvaluationBudgetScale = 16;

// A budget a sixteenth of a document's, open on this thread while it lives: the evaluator's and
// the processor's own budgets opened inside it count against it.
inline xacro::EvaluationBudget SmallEvaluationBudget() {
  return xacro::EvaluationBudget(xacro::kEvaluationBudgetItems / kEvaluationBudgetScale,
                                 xacro::kEvaluationBudgetBytes / kEvaluationBudgetScale,
                                 xacro::kContainerBudgetItems / kEvaluationBudgetScale);
}

}  // namespace urdfsnap::fuzz
