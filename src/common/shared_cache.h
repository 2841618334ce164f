// A process-wide cache of immutable objects made from files (meshes, textures, glyph atlases)
// that holds them only while someone else does: entries are weak, so memory is bounded by what the
// live render sessions use, and a long-running process that renders many robots does not grow.
// Each object is made once while it is alive, also under concurrent requests for the same key
// (the first caller makes it, the others wait for it).
#pragma once

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>

namespace urdfsnap {

template <typename Key, typename Value>
class SharedCache {
 public:
  using Pointer = std::shared_ptr<const Value>;

  // The object for `key` if one is still held anywhere, else the result of `make()`, cached
  // (weakly) for later callers. An exception from `make` reaches every waiting caller and is not
  // cached.
  Pointer Get(const Key& key, const std::function<Pointer()>& make) {
    std::promise<Pointer> promise;
    std::shared_future<Pointer> pending;
    {
      std::lock_guard lock(mutex_);
      Entry& entry = entries_[key];
      if (Pointer value = entry.value.lock()) return value;
      if (entry.loading.valid()) {
        pending = entry.loading;
      } else {
        entry.loading = promise.get_future().share();
      }
    }
    if (pending.valid()) return pending.get();
    try {
      Pointer value = make();
      promise.set_value(value);
      std::lock_guard lock(mutex_);
      entries_[key] = {value, {}};
      PurgeExpired();
      return value;
    } catch (...) {
      promise.set_exception(std::current_exception());
      std::lock_guard lock(mutex_);
      entries_.erase(key);
      throw;
    }
  }

 private:
  struct Entry {
    std::weak_ptr<const Value> value;
    std::shared_future<Pointer> loading;   // valid while the first caller makes the object
  };

  // Drops entries nobody holds any more, whenever the map has doubled since the last time.
  void PurgeExpired() {
    if (entries_.size() < purge_at_) return;
    for (auto it = entries_.begin(); it != entries_.end();) {
      it = it->second.value.expired() && !it->second.loading.valid() ? entries_.erase(it) : std::next(it);
    }
    purge_at_ = std::max<size_t>(64, 2 * entries_.size());
  }

  std::mutex mutex_;
  std::map<Key, Entry> entries_;
  size_t purge_at_ = 64;
};

}  // namespace urdfsnap
