// A value computed once per distinct key, from any thread: verify's CPU
// work that many checks share (a reference on one map's content, the ray
// cast a scene's maps are held against), done by whichever check asks
// first instead of by each.
#pragma once

#include <tbb/collaborative_call_once.h>

#include <algorithm>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>

namespace penumbra {

// Keys compare with ==, so that one holding images compares their content,
// not a hash of it: two keys share a value only when they are equal. A memo
// holds few keys (a variant's scenes times its distinct maps), so a linear
// search costs nothing beside what a value takes to make.
template <typename Key, typename Value>
class Memo {
 public:
  // The value for `key`, made by `make()` on the first call with a key
  // equal to it. A call with the same key meanwhile waits for that value
  // and helps with the parallel loops `make` starts (oneTBB's
  // collaborative_call_once), so that no core idles behind it. The value
  // lives as long as the memo.
  template <typename Make>
  const Value& get(const Key& key, Make&& make) {
    Slot& slot = slot_for(key);
    tbb::collaborative_call_once(slot.once, [&] { slot.value.emplace(make()); });
    return *slot.value;
  }

 private:
  struct Slot {
    explicit Slot(const Key& k) : key(k) {}
    Key key;
    tbb::collaborative_once_flag once;
    std::optional<Value> value;
  };

  Slot& slot_for(const Key& key) {
    const std::lock_guard lock(mutex_);
    const auto found = std::find_if(slots_.begin(), slots_.end(),
                                    [&](const std::unique_ptr<Slot>& s) { return s->key == key; });
    if (found != slots_.end()) return **found;
    return *slots_.emplace_back(std::make_unique<Slot>(key));
  }

  std::mutex mutex_;
  std::deque<std::unique_ptr<Slot>> slots_;
};

}  // namespace penumbra
