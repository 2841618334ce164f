// Bounds on the lists and strings xacro expressions build, so that no expression can exhaust
// memory or run for minutes: one list, tuple, dict, set or iteration holds at most kMaxListItems
// items and one string at most kMaxStringBytes bytes (both checked before they are built), and
// everything a document's expressions materialise (list items, copies made to iterate,
// comprehension steps, the bytes of every string built) is charged to one budget per document.
// The items of every list, tuple and dict made are charged to a second one: the work budget
// alone let one expression keep a million lists of long strings (1.2 GB, found by fuzzing).
// Real robot descriptions use a few thousand items and kilobytes of text; Python's xacro has no
// such limits and would run out of memory.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// The most items one list, tuple, dict, set or iteration may have (about 150 MB of values).
inline constexpr size_t kMaxListItems = size_t{1} << 20;

// The items all expressions of one document may materialise, comprehension steps included
// (about 600 MB of values if all were alive at once, about a second of work).
inline constexpr size_t kEvaluationBudgetItems = size_t{4} << 20;

// The items all lists, tuples and dicts made by one document's expressions may hold in all,
// however they were made (a method's result, a comprehension's, a conversion's): about 360 MB
// if all were alive at once, strings of 100 bytes included.
inline constexpr size_t kContainerBudgetItems = size_t{1} << 20;

// The longest string an expression or a text substitution may build (16 MiB).
inline constexpr size_t kMaxStringBytes = size_t{16} << 20;

// The bytes of text all expressions and substitutions of one document may build (256 MiB, the
// size limit of the expanded document).
inline constexpr size_t kEvaluationBudgetBytes = size_t{256} << 20;

// The budget of the expressions evaluated on this thread while it lives. Opening one while
// another is open on the thread does nothing: the outer one (a document's) keeps counting.
class EvaluationBudget {
 public:
  explicit EvaluationBudget(size_t items = kEvaluationBudgetItems, size_t bytes = kEvaluationBudgetBytes,
                            size_t container_items = kContainerBudgetItems);
  ~EvaluationBudget();
  EvaluationBudget(const EvaluationBudget&) = delete;
  EvaluationBudget& operator=(const EvaluationBudget&) = delete;

  // Charges `items` to the open budget; throws EvalError when it is spent. No-op without one.
  static void Charge(size_t items);

  // Charges the `items` of a list, tuple or dict being made to the open budget; throws EvalError
  // when it is spent. No-op without one.
  static void ChargeContainer(size_t items);

  // Charges `bytes` of text made (a string derived from another, a yaml file loaded) to the open
  // budget; throws EvalError when it is spent. No-op without one.
  static void ChargeBytes(size_t bytes);

 private:
  bool owner_ = false;
};

// Throws EvalError("WHAT too large: N items (the limit is ...)") when n > kMaxListItems; call it
// before building a list of n items.
void CheckListSize(Int n, const char* what);

// Throws EvalError("WHAT too large: N bytes (the limit is 16777216)") when n > kMaxStringBytes,
// else charges the n bytes to the open budget (EvalError when it is spent); call it before
// building a string of n bytes.
void CheckStringSize(size_t n, const char* what);

// Appends `piece` to `out`, a string being built (a repr, a document's text), after checking
// that it stays within kMaxStringBytes.
void AppendBounded(std::string& out, std::string_view piece, const char* what);

}  // namespace urdfsnap::xacro
