// CPython 3.11's set table and set algebra (Objects/setobject.c), on Values.
#include "xacro/internal/python_set.h"

#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/python_hash.h"

namespace urdfsnap::xacro {
namespace {

constexpr size_t kMinSize = 8;
constexpr size_t kLinearProbes = 9;
constexpr int kPerturbShift = 5;

// the hash a key is looked up by: a set stands for the frozenset of its items
Value LookupKey(const Value& key) {
  if (key.type != Value::Type::kSet) return key;
  Value frozen = MakeSet(Value::Type::kFrozenSet);
  SetOf(frozen).Update(key);
  return frozen;
}

bool SameObject(const Value& a, const Value& b) { return a.object == b.object; }

Value NewLike(const Value& s) { return MakeSet(s.type); }

// s.difference_update(s) and s.symmetric_difference_update(s) empty s
bool EmptiedBySelf(const Value& s, const Value& other) {
  if (!other.IsAnySet() || !SameObject(other, s)) return false;
  SetOf(s).Clear();
  return true;
}

}  // namespace

SetTable::SetTable() : table_(kMinSize) {}

uint32_t SetTable::StoreKey(const Value& key) {
  keys_.push_back(key);
  return static_cast<uint32_t>(keys_.size() - 1);
}

size_t SetTable::Lookup(const Value& key, int64_t hash) const {
  size_t i = static_cast<uint64_t>(hash) & mask_;
  uint64_t perturb = static_cast<uint64_t>(hash);
  while (true) {
    size_t probes = i + kLinearProbes <= mask_ ? kLinearProbes : 0;
    for (size_t e = i;; ++e) {
      const Slot& slot = table_[e];
      if (slot.hash == 0 && slot.key == kEmpty) return kNotFound;
      if (slot.hash == hash && slot.key < kDummy && Equal(keys_[slot.key], key)) return e;
      if (probes-- == 0) break;
    }
    perturb >>= kPerturbShift;
    i = (i * 5 + 1 + perturb) & mask_;
  }
}

void SetTable::AddEntry(const Value& key, int64_t hash) {
  size_t i = static_cast<uint64_t>(hash) & mask_;
  uint64_t perturb = static_cast<uint64_t>(hash);
  Slot* free_slot = nullptr;
  while (true) {
    size_t probes = i + kLinearProbes <= mask_ ? kLinearProbes : 0;
    for (size_t e = i;; ++e) {
      Slot& slot = table_[e];
      if (slot.hash == 0 && slot.key == kEmpty) {
        if (used_ >= kMaxListItems) CheckListSize(static_cast<Int>(used_ + 1), "set");
        if (free_slot) {
          // a slot a removal left behind
          *free_slot = Slot{hash, StoreKey(key)};
          ++used_;
          return;
        }
        slot = Slot{hash, StoreKey(key)};
        ++fill_;
        ++used_;
        if (fill_ * 5 >= mask_ * 3) Resize(used_ > 50000 ? used_ * 2 : used_ * 4);
        return;
      }
      if (slot.hash == hash && slot.key < kDummy && Equal(keys_[slot.key], key)) return;
      if (slot.key == kDummy && !free_slot) free_slot = &slot;
      if (probes-- == 0) break;
    }
    perturb >>= kPerturbShift;
    i = (i * 5 + 1 + perturb) & mask_;
  }
}

void SetTable::InsertClean(std::vector<Slot>& table, size_t mask, uint32_t key, int64_t hash) {
  size_t i = static_cast<uint64_t>(hash) & mask;
  uint64_t perturb = static_cast<uint64_t>(hash);
  while (true) {
    if (table[i].key == kEmpty) {
      table[i] = Slot{hash, key};
      return;
    }
    if (i + kLinearProbes <= mask) {
      for (size_t j = 1; j <= kLinearProbes; ++j) {
        if (table[i + j].key == kEmpty) {
          table[i + j] = Slot{hash, key};
          return;
        }
      }
    }
    perturb >>= kPerturbShift;
    i = (i * 5 + 1 + perturb) & mask;
  }
}

void SetTable::Resize(size_t min_used) {
  size_t size = kMinSize;
  while (size <= min_used) size <<= 1;
  // a minimal table without removals stays as it is
  if (size == kMinSize && table_.size() == kMinSize && fill_ == used_) return;
  std::vector<Slot> table(size);
  std::vector<Value> keys;
  keys.reserve(used_);
  for (const Slot& slot : table_) {
    if (slot.key >= kDummy) continue;
    keys.push_back(std::move(keys_[slot.key]));
    InsertClean(table, size - 1, static_cast<uint32_t>(keys.size() - 1), slot.hash);
  }
  table_ = std::move(table);
  keys_ = std::move(keys);
  mask_ = size - 1;
  fill_ = used_;
}

void SetTable::PurgeDummies() {
  if (fill_ - used_ > mask_ / 4) Resize(used_ > 50000 ? used_ * 2 : used_ * 4);
}

void SetTable::Add(const Value& key) { AddEntry(key, Hash(key)); }

bool SetTable::ContainsEntry(const Value& key, int64_t hash) const { return Lookup(key, hash) != kNotFound; }

bool SetTable::Contains(const Value& key) const {
  const Value k = LookupKey(key);
  return ContainsEntry(k, Hash(k));
}

bool SetTable::DiscardEntry(const Value& key, int64_t hash) {
  const size_t e = Lookup(key, hash);
  if (e == kNotFound) return false;
  keys_[table_[e].key] = Value::None();
  table_[e] = Slot{-1, kDummy};
  --used_;
  return true;
}

bool SetTable::Discard(const Value& key) {
  const Value k = LookupKey(key);
  return DiscardEntry(k, Hash(k));
}

void SetTable::Clear() {
  table_.assign(kMinSize, Slot{});
  keys_.clear();
  mask_ = kMinSize - 1;
  fill_ = used_ = 0;
}

Value SetTable::Pop() {
  if (used_ == 0) throw EvalError("'pop from an empty set'");
  // CPython's search finger: the next pop starts after the last one
  size_t e = finger_ & mask_;
  while (table_[e].key >= kDummy) e = e == mask_ ? 0 : e + 1;
  Value key = std::move(keys_[table_[e].key]);
  table_[e] = Slot{-1, kDummy};
  --used_;
  finger_ = e + 1;
  return key;
}

void SetTable::Merge(const SetTable& other) {
  if (&other == this || other.used_ == 0) return;
  if ((fill_ + other.used_) * 5 >= mask_ * 3) Resize((used_ + other.used_) * 2);
  if (fill_ == 0 && mask_ == other.mask_ && other.fill_ == other.used_) {
    // an empty table of the same size: a slot-for-slot copy
    table_ = other.table_;
    keys_ = other.keys_;
    fill_ = other.fill_;
    used_ = other.used_;
    return;
  }
  if (fill_ == 0) {
    other.ForEachEntry([&](const Value& key, int64_t hash) { InsertClean(table_, mask_, StoreKey(key), hash); });
    fill_ = used_ = other.used_;
    return;
  }
  other.ForEachEntry([&](const Value& key, int64_t hash) { AddEntry(key, hash); });
}

void SetTable::Update(const Value& iterable) {
  if (iterable.IsAnySet()) {
    Merge(SetOf(iterable));
    return;
  }
  if (iterable.type == Value::Type::kDict && !iterable.wrapped) {
    const size_t n = iterable.dict->items.size();
    if ((fill_ + n) * 5 >= mask_ * 3) Resize((used_ + n) * 2);
    for (const auto& item : iterable.dict->items) AddEntry(item.first, Hash(item.first));
    return;
  }
  const NextFunction next = IterateLazily(iterable);
  while (std::optional<Value> item = next()) Add(*item);
}

ValueList SetTable::Keys() const {
  ValueList out;
  out.reserve(used_);
  ForEachEntry([&](const Value& key, int64_t) { out.push_back(key); });
  return out;
}

SetTable& SetOf(const Value& v) { return static_cast<SetTable&>(*v.object); }

Value MakeSet(Value::Type type) {
  Value r;
  r.type = type;
  r.object = std::make_shared<SetTable>();
  return r;
}

Value SetFromIterable(Value::Type type, const Value& iterable) {
  if (type == Value::Type::kFrozenSet && iterable.type == Value::Type::kFrozenSet) return iterable;
  Value r = MakeSet(type);
  SetOf(r).Update(iterable);
  return r;
}

Value SetCopy(const Value& s) {
  Value r = NewLike(s);
  SetOf(r).Update(s);
  return r;
}

Value SetUnion(const Value& s, const ValueList& others) {
  Value r = SetCopy(s);
  for (const Value& other : others) {
    if (other.IsAnySet() && SameObject(other, s)) continue;
    SetOf(r).Update(other);
  }
  return r;
}

Value SetIntersection(const Value& s, const Value& other) {
  if (other.IsAnySet() && SameObject(other, s)) return SetCopy(s);
  Value r = NewLike(s);
  SetTable& result = SetOf(r);
  if (other.IsAnySet()) {
    // walk the smaller set, look up in the larger
    const SetTable* big = &SetOf(s);
    const SetTable* small = &SetOf(other);
    if (small->size() > big->size()) std::swap(big, small);
    small->ForEachEntry([&](const Value& key, int64_t hash) {
      if (big->ContainsEntry(key, hash)) result.AddEntry(key, hash);
    });
    return r;
  }
  const NextFunction next = IterateLazily(other);
  while (std::optional<Value> key = next()) {
    const int64_t hash = Hash(*key);
    if (SetOf(s).ContainsEntry(*key, hash)) result.AddEntry(*key, hash);
  }
  return r;
}

void SetDifferenceUpdate(const Value& s, const Value& other) {
  if (EmptiedBySelf(s, other)) return;
  SetTable& table = SetOf(s);
  if (other.IsAnySet()) {
    // a much larger other set is first cut down to the common keys
    const Value keys = SetOf(other).size() >> 3 > table.size() ? SetIntersection(s, other) : other;
    SetOf(keys).ForEachEntry([&](const Value& key, int64_t hash) { table.DiscardEntry(key, hash); });
  } else {
    const NextFunction next = IterateLazily(other);
    while (std::optional<Value> key = next()) table.Discard(*key);
  }
  table.PurgeDummies();
}

Value SetDifference(const Value& s, const Value& other) {
  size_t other_size = 0;
  if (other.IsAnySet()) {
    other_size = SetOf(other).size();
  } else if (other.type == Value::Type::kDict && !other.wrapped) {
    other_size = other.dict->items.size();
  } else {
    Value r = SetCopy(s);
    SetDifferenceUpdate(r, other);
    return r;
  }
  if ((SetOf(s).size() >> 2) > other_size) {
    Value r = SetCopy(s);
    SetDifferenceUpdate(r, other);
    return r;
  }
  Value r = NewLike(s);
  SetTable& result = SetOf(r);
  SetOf(s).ForEachEntry([&](const Value& key, int64_t hash) {
    const bool found = other.IsAnySet() ? SetOf(other).ContainsEntry(key, hash)
                                        : other.dict->Find(key) != DictItems::kNone;
    if (!found) result.AddEntry(key, hash);
  });
  return r;
}

void SetSymmetricDifferenceUpdate(const Value& s, const Value& other) {
  if (EmptiedBySelf(s, other)) return;
  SetTable& table = SetOf(s);
  auto toggle = [&](const Value& key, int64_t hash) {
    if (!table.DiscardEntry(key, hash)) table.AddEntry(key, hash);
  };
  if (other.type == Value::Type::kDict && !other.wrapped) {
    for (const auto& item : other.dict->items) toggle(item.first, Hash(item.first));
    return;
  }
  const Value keys = other.IsAnySet() ? other : SetFromIterable(s.type, other);
  // a snapshot: toggling may resize the table being read when other is s's copy
  SetOf(keys).ForEachEntry(toggle);
}

Value SetSymmetricDifference(const Value& s, const Value& other) {
  Value r = MakeSet(s.type);
  SetOf(r).Update(other);
  SetSymmetricDifferenceUpdate(r, s);
  return r;
}

bool IsSubset(const Value& s, const Value& other) {
  if (!other.IsAnySet()) return SetOf(SetIntersection(s, other)).size() == SetOf(s).size();
  if (SetOf(s).size() > SetOf(other).size()) return false;
  bool subset = true;
  SetOf(s).ForEachEntry([&](const Value& key, int64_t hash) {
    if (subset && !SetOf(other).ContainsEntry(key, hash)) subset = false;
  });
  return subset;
}

bool IsSuperset(const Value& s, const Value& other) {
  if (other.IsAnySet()) return IsSubset(other, s);
  const NextFunction next = IterateLazily(other);
  while (std::optional<Value> key = next()) {
    if (!SetOf(s).Contains(*key)) return false;
  }
  return true;
}

bool IsDisjoint(const Value& s, const Value& other) {
  if (other.IsAnySet() && SameObject(other, s)) return SetOf(s).size() == 0;
  if (other.IsAnySet()) {
    const SetTable* big = &SetOf(s);
    const SetTable* small = &SetOf(other);
    if (small->size() > big->size()) std::swap(big, small);
    bool disjoint = true;
    small->ForEachEntry([&](const Value& key, int64_t hash) {
      if (disjoint && big->ContainsEntry(key, hash)) disjoint = false;
    });
    return disjoint;
  }
  const NextFunction next = IterateLazily(other);
  while (std::optional<Value> key = next()) {
    if (SetOf(s).Contains(*key)) return false;
  }
  return true;
}

std::string SetRepr(const Value& s) {
  const bool frozen = s.type == Value::Type::kFrozenSet;
  if (SetOf(s).size() == 0) return frozen ? "frozenset()" : "set()";
  std::string out = frozen ? "frozenset({" : "{";
  bool first = true;
  SetOf(s).ForEachEntry([&](const Value& key, int64_t) {
    if (!first) out += ", ";
    first = false;
    AppendBounded(out, Repr(key), "repr");
  });
  return out + (frozen ? "})" : "}");
}

}  // namespace urdfsnap::xacro
