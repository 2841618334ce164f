// Python's lazy iterables: the iterator objects map, filter, zip, enumerate and reversed return
// (each item made when it is asked for, used up once, printed "<zip object at 0x...>"), and the
// range object ("range(0, 3)": length, items, slices and `in` computed without building a list).
#pragma once

#include <string>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// An iterator: its Python type name ("zip", "map", "list_reverseiterator", ...) and the function
// giving its next item. Once it has ended it stays ended.
class Iterator : public Object {
 public:
  Iterator(std::string type_name, NextFunction next);
  const std::string& type_name() const { return type_name_; }
  std::optional<Value> Next();

 private:
  std::string type_name_;
  NextFunction next_;
  bool ended_ = false;
};

Iterator& IteratorOf(const Value& v);
Value MakeIterator(std::string type_name, NextFunction next);

// map(f, *iterables), filter(f or None, iterable), zip(*iterables, strict), enumerate(iterable,
// start), reversed(sequence): the iterables are opened now (an error if one is not iterable),
// their items are read as the result is iterated.
Value MapIterator(const Value& f, const ValueList& iterables);
Value FilterIterator(const Value& f, const Value& iterable);
Value ZipIterator(const ValueList& iterables, bool strict);
Value EnumerateIterator(const Value& iterable, Int start);
Value ReversedIterator(const Value& sequence);

// range(start, stop, step) from Python's arguments (ints or bools; step not 0).
Value MakeRange(const ValueList& args);
// len(r) (the range constructor refuses lengths beyond 127 bits)
Int RangeLength(const Value& r);
// r[index] with a negative index counting from the end; IndexError message past the end
Value RangeItem(const Value& r, Int index);
// x in r: arithmetic for ints, comparison with each item otherwise
bool RangeContains(const Value& r, const Value& x);
// range == range: the same items
bool RangeEqual(const Value& a, const Value& b);
// "range(0, 3)", "range(0, 10, 2)"
std::string RangeRepr(const Value& r);
// the items of r, one by one, refusing ranges longer than kMaxListItems up front
NextFunction IterateRange(const Value& r);

}  // namespace urdfsnap::xacro
