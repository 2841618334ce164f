// EvaluationBudget: counters per thread, owned by the outermost open budget.
#include "xacro/internal/evaluation_budget.h"

#include <string>

namespace urdfsnap::xacro {

namespace {

struct Counter {
  bool open = false;
  size_t items_left = 0, items_total = 0;
  size_t bytes_left = 0, bytes_total = 0;
  size_t containers_left = 0, containers_total = 0;
};

thread_local Counter counter;

}  // namespace

EvaluationBudget::EvaluationBudget(size_t items, size_t bytes, size_t container_items) {
  if (counter.open) return;
  counter = {true, items, items, bytes, bytes, container_items, container_items};
  owner_ = true;
}

EvaluationBudget::~EvaluationBudget() {
  if (owner_) counter = {};
}

void EvaluationBudget::Charge(size_t items) {
  if (!counter.open) return;
  if (items > counter.items_left) {
    counter.items_left = 0;
    throw EvalError("expressions build more than " + std::to_string(counter.items_total) +
                    " list items in all (runaway comprehension or range()?)");
  }
  counter.items_left -= items;
}

void EvaluationBudget::ChargeContainer(size_t items) {
  if (!counter.open) return;
  if (items > counter.containers_left) {
    counter.containers_left = 0;
    throw EvalError("expressions make lists, tuples and dicts of more than " +
                    std::to_string(counter.containers_total) + " items in all (runaway comprehension?)");
  }
  counter.containers_left -= items;
}

void CheckListSize(Int n, const char* what) {
  if (n > Int(kMaxListItems)) {
    throw EvalError(std::string(what) + " too large: " + ToStr(Value::Integer(n)) +
                    " items (the limit is " + std::to_string(kMaxListItems) + ")");
  }
  EvaluationBudget::Charge(static_cast<size_t>(n));
}

void CheckStringSize(size_t n, const char* what) {
  if (n > kMaxStringBytes) {
    throw EvalError(std::string(what) + " too large: " + std::to_string(n) + " bytes (the limit is " +
                    std::to_string(kMaxStringBytes) + ")");
  }
  EvaluationBudget::ChargeBytes(n);
}

void EvaluationBudget::ChargeBytes(size_t bytes) {
  if (!counter.open) return;
  if (bytes > counter.bytes_left) {
    counter.bytes_left = 0;
    throw EvalError("expressions build more than " + std::to_string(counter.bytes_total) +
                    " bytes of text in all (runaway string building?)");
  }
  counter.bytes_left -= bytes;
}

void AppendBounded(std::string& out, std::string_view piece, const char* what) {
  if (out.size() + piece.size() > kMaxStringBytes) CheckStringSize(out.size() + piece.size(), what);
  out += piece;
}

}  // namespace urdfsnap::xacro
