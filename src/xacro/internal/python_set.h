// Python's set and frozenset: CPython 3.11's open-addressing hash table (Objects/setobject.c:
// linear probes, perturbation, fill and resize rules, dummies left by removals), reproduced so
// that a set iterates, prints and pops in exactly CPython's order, and the set algebra built on
// it (union, intersection, differences, subset tests) in CPython's order of insertions.
#pragma once

#include <cstdint>
#include <vector>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

class SetTable : public Object {
 public:
  SetTable();

  // len(s)
  size_t size() const { return used_; }

  // s.add(key): hashes the key (EvalError for unhashable keys) and inserts it unless an equal
  // key is there. At most kMaxListItems keys.
  void Add(const Value& key);
  void AddEntry(const Value& key, int64_t hash);

  // key in s; a set key is looked up as the frozenset of its items, as CPython does.
  bool Contains(const Value& key) const;
  bool ContainsEntry(const Value& key, int64_t hash) const;

  // s.discard(key): whether the key was there (a set key as for Contains).
  bool Discard(const Value& key);
  bool DiscardEntry(const Value& key, int64_t hash);

  // s.clear(), s.pop() (KeyError message "pop from an empty set" when empty)
  void Clear();
  Value Pop();

  // s.update(iterable), in CPython's order: a set merged slot by slot, a dict's keys with one
  // resize first, any other iterable item by item.
  void Update(const Value& iterable);

  // the keys in table order with their hashes
  template <class F>
  void ForEachEntry(F&& f) const {
    for (const Slot& slot : table_) {
      if (slot.key < kDummy) f(keys_[slot.key], slot.hash);
    }
  }
  ValueList Keys() const;

  // rebuilds the table when more than a quarter of it are slots left by removals (after a
  // difference_update, as CPython does)
  void PurgeDummies();

 private:
  static constexpr uint32_t kEmpty = UINT32_MAX;
  static constexpr size_t kNotFound = SIZE_MAX;
  static constexpr uint32_t kDummy = UINT32_MAX - 1;
  struct Slot {
    int64_t hash = 0;
    uint32_t key = kEmpty;  // index into keys_, kEmpty or kDummy
  };

  void Merge(const SetTable& other);
  void Resize(size_t min_used);
  static void InsertClean(std::vector<Slot>& table, size_t mask, uint32_t key, int64_t hash);
  // the index of the slot holding an equal key, or kNotFound
  size_t Lookup(const Value& key, int64_t hash) const;
  uint32_t StoreKey(const Value& key);

  std::vector<Slot> table_;
  std::vector<Value> keys_;  // the keys the slots point at (removed ones stay until a resize)
  size_t mask_ = 7, fill_ = 0, used_ = 0, finger_ = 0;
};

// The table of a set or frozenset value.
SetTable& SetOf(const Value& v);

// A new empty set (type kSet) or frozenset (kFrozenSet).
Value MakeSet(Value::Type type);

// set(iterable) / frozenset(iterable) of the given type.
Value SetFromIterable(Value::Type type, const Value& iterable);

// s.copy(), a new set of the same type filled as CPython's set_copy fills it.
Value SetCopy(const Value& s);

// The set algebra; the result has s's type. `other` may be any iterable except for the
// operators (`|`, `&`, `-`, `^`), which want two sets (the caller checks).
Value SetUnion(const Value& s, const ValueList& others);
Value SetIntersection(const Value& s, const Value& other);
Value SetDifference(const Value& s, const Value& other);
Value SetSymmetricDifference(const Value& s, const Value& other);
// the in-place forms of the methods (intersection_update, ...): s becomes the result
void SetDifferenceUpdate(const Value& s, const Value& other);
void SetSymmetricDifferenceUpdate(const Value& s, const Value& other);

// s.issubset(other), s.issuperset(other), s.isdisjoint(other) for any iterable other.
bool IsSubset(const Value& s, const Value& other);
bool IsSuperset(const Value& s, const Value& other);
bool IsDisjoint(const Value& s, const Value& other);

// repr: "{1, 2}", "set()", "frozenset({1, 2})", "frozenset()".
std::string SetRepr(const Value& s);

}  // namespace urdfsnap::xacro
